#pragma once

#include "mocap/math/banded_cholesky.h"

#include <Eigen/Core>

#include <vector>

namespace mocap {

/// Options of the least-squares B-spline. `degree` is the paper's n in eqs 11–12: each span is
/// a polynomial of degree n blending n + 1 control points, so the paper's "third order" curve is
/// degree 3 (cubic). Textbooks that count order as degree + 1 would call it order 4.
struct BSplineFitOptions
{
  int degree = 3;            ///< 2..7
  double knotSpacing = 4.0;  ///< frames between interior knots, ≥ 1; the run length is split evenly
};

/// Smallest and largest accepted degree, and the shortest run a fit can change (shorter runs
/// come back unchanged: with degree + 1 samples the spline can only interpolate them). O(1).
inline constexpr int kMinBSplineDegree = 2;
inline constexpr int kMaxBSplineDegree = 7;
[[nodiscard]] inline Eigen::Index minBSplineRunLength(int degree)
{
  return degree + 2;
}

/// Throws InvalidArgument unless the degree (n of eqs 11–12) is in 2..7 and the knot spacing is
/// finite and ≥ 1. O(1).
void checkBSplineFitOptions(const BSplineFitOptions& options);

/// Eq 12: the uniform B-spline blending function F_{k,n}(t) = 1/n! Σ_{j=0}^{n−k} (−1)^j C(n+1, j)
/// (t + n − k − j)^n for k = 0..n, t ∈ [0, 1]: the weight of control point P_{i+k} in span i
/// (eq 11). The fit evaluates this polynomial (expanded once per degree) on interior spans and the
/// Cox–de Boor recursion, which reduces to it there, on the clamped end spans. O(n²).
[[nodiscard]] double uniformBSplineBasis(int k, int n, double t);

/// A least-squares fit of a clamped ("quasi-uniform", the paper's triple-vertex construction
/// for n = 3) B-spline to `sampleCount` equally spaced samples, precomputed once and applied to
/// any number of signals of that length (precompute/solve split).
///
/// The knot vector has n + 1 copies of each end and S = round((N − 1) / knotSpacing) equal
/// interior spans, at least 1 and at most min(N − n − 1, (N − 1) / 1.5): the fit stays a strict
/// least-squares problem, and spans of at least 1.5 frames keep it well conditioned at every
/// degree (so a spacing below 1.5 acts as 1.5). The end control points are pinned to the first and last
/// sample, so the curve passes through both end points; the other S + n − 2 control points minimise the
/// squared error (eqs 11–12 fitted, not interpolated). Polynomials of degree ≤ n are reproduced exactly.
///
/// Construction O(N · n²) (basis by eq 12, by Cox–de Boor on the end spans; banded normal
/// equations of half-bandwidth n, banded LDLᵀ); each fit O(N · n) per column.
class BSplineFitter
{
public:
  /// Throws InvalidArgument for bad options or sampleCount < minBSplineRunLength(degree).
  BSplineFitter(Eigen::Index sampleCount, const BSplineFitOptions& options);

  [[nodiscard]] Eigen::Index sampleCount() const { return m_sampleCount; }
  [[nodiscard]] int degree() const { return m_degree; }
  [[nodiscard]] Eigen::Index spanCount() const { return m_spanCount; }
  [[nodiscard]] Eigen::Index controlPointCount() const { return m_spanCount + m_degree; }

  /// Control points (controlPointCount() × columns) of the fit to `samples` (sampleCount() ×
  /// any number of columns, every sample used). Throws InvalidArgument on a size mismatch or a
  /// non-finite sample. O(N · n) per column.
  [[nodiscard]] Eigen::MatrixXd controlPoints(const Eigen::Ref<const Eigen::MatrixXd>& samples) const;
  /// The fitted curve at the sample positions, same shape as `samples`. O(N · n) per column.
  [[nodiscard]] Eigen::MatrixXd fit(const Eigen::Ref<const Eigen::MatrixXd>& samples) const;
  /// The same written into `result` (same shape as `samples`, may not alias it). O(N · n) per column.
  void fit(const Eigen::Ref<const Eigen::MatrixXd>& samples, Eigen::Ref<Eigen::MatrixXd> result) const;

private:
  // Control points as rows (controlPointCount() × columns, row-major).
  [[nodiscard]] BandedCholesky::Band solve(const Eigen::Ref<const Eigen::MatrixXd>& samples) const;

  Eigen::Index m_sampleCount = 0;
  int m_degree = 3;
  Eigen::Index m_spanCount = 1;
  std::vector<Eigen::Index> m_firstControl;  // per sample: first of its n + 1 controls
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> m_basis;  // N × (n + 1)
  BandedCholesky m_normal;                                                         // inner controls 1..M−2
  Eigen::VectorXd m_startCoupling;  // (BᵀB)(a, 0) for inner controls a, the pinned first control's share
  Eigen::VectorXd m_endCoupling;    // (BᵀB)(a, M − 1)
};

/// One-shot fit of `samples` (#samples × any columns, all valid). Runs shorter than
/// minBSplineRunLength(degree) come back unchanged. Throws InvalidArgument for bad options or a
/// non-finite sample. O(N · n²).
[[nodiscard]] Eigen::MatrixXd fitBSpline(const Eigen::Ref<const Eigen::MatrixXd>& samples,
                                         const BSplineFitOptions& options = {});

} // namespace mocap
