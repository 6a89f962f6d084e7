#include "mocap/cleaning/butterworth_filter.h"

#include "mocap/base/error.h"
#include "mocap/math/pi.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace mocap {

namespace {

constexpr Eigen::Index kMinCurvatureWindow = 16;

void checkRates(double frameRate, double cutoffHz)
{
  if (!std::isfinite(frameRate) || frameRate <= 0.0)
    throw InvalidArgument("Butterworth filter: frame rate must be finite and positive, not " +
                          std::to_string(frameRate));
  if (!std::isfinite(cutoffHz) || cutoffHz <= 0.0 || cutoffHz >= 0.5 * frameRate)
    throw InvalidArgument("Butterworth cutoff must lie between 0 and the Nyquist frequency (" +
                          std::to_string(0.5 * frameRate) + " Hz), not " + std::to_string(cutoffHz) + " Hz");
}

double analogCutoff(double frameRate, double cutoffHz)
{
  return std::tan(kPi * cutoffHz / frameRate) / butterworthPassCorrection();
}

// Weights w such that wᵀ y[0..W−1] is the k² coefficient of the least-squares cubic through
// (k, y[k]), k = 0..W−1 (abscissae scaled to [0, 1] for conditioning).
Eigen::VectorXd curvatureWeights(Eigen::Index window)
{
  const double scale = static_cast<double>(window - 1);
  Eigen::MatrixXd vandermonde(window, 4);
  for (Eigen::Index k = 0; k < window; ++k) {
    const double u = static_cast<double>(k) / scale;
    vandermonde.row(k) << 1.0, u, u * u, u * u * u;
  }
  // Row 2 of (VᵀV)⁻¹Vᵀ through the 4 × 4 normal matrix: O(window), and well conditioned on [0, 1].
  const Eigen::Matrix4d gram = vandermonde.transpose() * vandermonde;
  const Eigen::Vector4d pick = gram.ldlt().solve(Eigen::Vector4d::UnitZ());
  return vandermonde * pick / (scale * scale);
}

// One causal pass over n rows of K side-by-side channels in place (row i of channel c at
// x[i · step + c]), each channel starting in the steady state of its first value. The recursion is
// a chain of dependent multiply-adds; running K channels together lets their chains overlap.
template <int K>
void filterPass(const Biquad& f, double* x, Eigen::Index n, Eigen::Index step)
{
  constexpr auto k = static_cast<std::size_t>(K);
  std::array<double, k> x1{}, x2{}, y1{}, y2{};
  for (std::size_t c = 0; c < k; ++c)
    x1[c] = x2[c] = y1[c] = y2[c] = x[c];
  for (Eigen::Index i = 0; i < n; ++i) {
    double* row = x + i * step;
    for (std::size_t c = 0; c < k; ++c) {
      const double v = row[c];
      const double y = f.b0 * v + f.b1 * x1[c] + f.b2 * x2[c] - f.a1 * y1[c] - f.a2 * y2[c];
      x2[c] = x1[c];
      x1[c] = v;
      y2[c] = y1[c];
      y1[c] = y;
      row[c] = y;
    }
  }
}

// Forward then backward over rows of a row-major buffer with `columns` channels.
void filterBothWays(const Biquad& f, double* data, Eigen::Index rows, Eigen::Index columns)
{
  double* last = data + (rows - 1) * columns;
  if (columns == 3) {
    filterPass<3>(f, data, rows, 3);
    filterPass<3>(f, last, rows, -3);
    return;
  }
  for (Eigen::Index c = 0; c < columns; ++c) {
    filterPass<1>(f, data + c, rows, columns);
    filterPass<1>(f, last + c, rows, -columns);
  }
}

} // namespace

double butterworthPassCorrection()
{
  return std::pow(std::sqrt(2.0) - 1.0, 0.25);
}

Biquad butterworthLowPass(double frameRate, double cutoffHz)
{
  checkRates(frameRate, cutoffHz);
  const double k = analogCutoff(frameRate, cutoffHz);
  const double root2 = std::sqrt(2.0);
  const double norm = 1.0 + root2 * k + k * k;
  Biquad f;
  f.b0 = k * k / norm;
  f.b1 = 2.0 * f.b0;
  f.b2 = f.b0;
  f.a1 = 2.0 * (k * k - 1.0) / norm;
  f.a2 = (1.0 - root2 * k + k * k) / norm;
  return f;
}

double butterworthGain(double frequencyHz, double frameRate, double cutoffHz)
{
  checkRates(frameRate, cutoffHz);
  const double ratio = std::tan(kPi * std::abs(frequencyHz) / frameRate) / analogCutoff(frameRate, cutoffHz);
  return 1.0 / (1.0 + ratio * ratio * ratio * ratio);
}

Eigen::Index butterworthPadLength(Eigen::Index sampleCount, double frameRate, double cutoffHz)
{
  const auto wanted = static_cast<Eigen::Index>(std::ceil(3.0 * frameRate / cutoffHz));
  return std::max(Eigen::Index{0}, std::min(sampleCount - 1, wanted));
}

Eigen::MatrixXd butterworthFilter(const Eigen::Ref<const Eigen::MatrixXd>& samples, double frameRate,
                                  double cutoffHz)
{
  const Biquad section = butterworthLowPass(frameRate, cutoffHz);
  if (!samples.allFinite())
    throw InvalidArgument("Butterworth filter: samples must be finite");
  const Eigen::Index n = samples.rows();
  if (n < kMinButterworthRunLength)
    return samples;
  const Eigen::Index pad = butterworthPadLength(n, frameRate, cutoffHz);
  // The curvature of the end is only trusted from a cubic fitted to enough samples; on shorter
  // runs a noisy or jumping end would be extrapolated quadratically, so those get plain odd reflection.
  const Eigen::Index window = std::min(n, pad + 1);
  const Eigen::VectorXd curvature =
      window >= kMinCurvatureWindow ? curvatureWeights(window) : Eigen::VectorXd::Zero(window);
  // Padded copy, row-major so the channels of one frame sit side by side for filterBothWays.
  const Eigen::Index columns = samples.cols();
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> extended(n + 2 * pad, columns);
  extended.middleRows(pad, n) = samples;
  for (Eigen::Index c = 0; c < columns; ++c) {
    const auto y = samples.col(c);
    // Odd reflection through the end sample plus twice the even (k²) part of the local cubic:
    // exact continuation of any cubic, so the padded signal has no kink for the filter to ring on.
    const double headCurvature = curvature.dot(y.head(window));
    const double tailCurvature = curvature.dot(y.tail(window).reverse());
    for (Eigen::Index k = 1; k <= pad; ++k) {
      const double k2 = static_cast<double>(k * k);
      extended(pad - k, c) = 2.0 * y(0) - y(k) + 2.0 * headCurvature * k2;
      extended(pad + n - 1 + k, c) = 2.0 * y(n - 1) - y(n - 1 - k) + 2.0 * tailCurvature * k2;
    }
  }
  filterBothWays(section, extended.data(), extended.rows(), columns);
  Eigen::MatrixXd result = extended.middleRows(pad, n);
  return result;
}

} // namespace mocap
