#pragma once

#include <Eigen/Core>

namespace mocap {

struct SavitzkyGolayOptions
{
  int window = 9;  ///< samples in the moving window: odd, 3..1001
  int degree = 3;  ///< degree of the local polynomial: 0..min(window − 1, 10)
};

/// Throws InvalidArgument unless the window is odd and in 3..1001 and the degree in
/// 0..min(window − 1, 10). O(1).
void checkSavitzkyGolayOptions(const SavitzkyGolayOptions& options);

/// The window × window matrix W whose row r holds the weights giving the value at window
/// position r of the least-squares polynomial of `degree` through the window's samples:
/// W = V (VᵀV)⁻¹ Vᵀ, V the Vandermonde matrix (orthonormal basis by Householder QR, abscissae
/// scaled to [−1, 1]). The middle row is the classic Savitzky–Golay (1964) convolution.
/// O(window² · degree). Not in the paper (Savitzky & Golay 1964).
[[nodiscard]] Eigen::MatrixXd savitzkyGolayWeights(const SavitzkyGolayOptions& options);

/// Savitzky–Golay smoothing of every column of `samples` (#samples × any columns, all valid).
/// Interior samples take the centred window; the first and last window/2 samples take the same
/// polynomial fitted to the first (last) full window, evaluated at their own position, so the ends
/// are neither shortened nor biased towards the middle. Polynomials up to `degree` pass
/// unchanged. Runs shorter than the window come back unchanged. Throws InvalidArgument for bad
/// options or a non-finite sample. O(#samples · window) per column. Not in the paper.
[[nodiscard]] Eigen::MatrixXd savitzkyGolay(const Eigen::Ref<const Eigen::MatrixXd>& samples,
                                            const SavitzkyGolayOptions& options = {});

} // namespace mocap
