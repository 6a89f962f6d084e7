#pragma once

#include <Eigen/Core>

namespace mocap {

/// LDLᵀ factorisation of a symmetric positive definite band matrix, the solver behind the
/// least-squares B-spline (banded normal equations) and the smoothing spline (Reinsch form).
///
/// A matrix of size n with half-bandwidth b is given by its lower band: an n × (b + 1) array with
/// band(i, k) = A(i, i − k); entries with i − k < 0 are ignored. Factorising costs O(n · b²),
/// each solve O(n · b) per right-hand side, and the band of the inverse O(n · b²). Implements no
/// paper equation itself; it solves the normal equations of the eqs 11–12 least-squares fit.
class BandedCholesky
{
public:
  using Band = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  BandedCholesky() = default;
  /// Factorises `lower`; throws InvalidArgument when the matrix is not (numerically) positive
  /// definite or the band is malformed. O(n · b²).
  explicit BandedCholesky(Band lower);

  [[nodiscard]] Eigen::Index size() const { return m_factor.rows(); }
  [[nodiscard]] Eigen::Index bandwidth() const { return m_factor.cols() - 1; }

  /// Overwrites each column of `rhs` (n rows) with A⁻¹ times it. O(n · b) per column.
  void solveInPlace(Eigen::Ref<Eigen::MatrixXd> rhs) const;
  /// The same for right-hand sides stored row-major (n × k, one unknown's k values side by side),
  /// solved without a copy. O(n · b · k).
  void solveInPlace(Band& rhs) const;

  /// The band of A⁻¹ (same layout as the input: result(i, k) = A⁻¹(i, i − k)), by the recurrence of
  /// Hutchinson & de Hoog (1985) that needs only the factor; used for traces of influence
  /// matrices such as tr(A⁻¹ M) with M of the same bandwidth. O(n · b²).
  [[nodiscard]] Band inverseBand() const;

private:
  Band m_factor;  // column 0: D(i); column k ≥ 1: L(i, i − k) of the unit lower factor
};

} // namespace mocap
