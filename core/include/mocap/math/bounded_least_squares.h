#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace mocap {

/// min ‖A·w − b‖² subject to lower ≤ w ≤ upper, for many right-hand sides b with the same A
/// (the blendshape weights of every frame, Wellein et al. 2007 §1: "optimal linear combination of
/// blendshapes with minimal least-square error", weights in [0, 1]). Precompute/solve split: the
/// constructor forms AᵀA once; solve() runs a primal active-set method (Lawson & Hanson's NNLS
/// generalised to two bounds, as in Stark & Parker's BVLS) on the normal equations.
///
/// A rank-deficient A (fewer measured coordinates than weights, e.g. a small marker subset) has
/// many minimisers; a ridge of 1e-12·trace(AᵀA)/#weights picks the one of least norm among them
/// and leaves a full-rank problem's solution unchanged to ~1e-12 relative.
class BoundedLeastSquares
{
public:
  /// `a` is #equations × #weights. With `ridge` > 0 the problem is min ‖A·w − b‖² + ridge·‖w‖²
  /// (added to AᵀA's diagonal). O(#equations · #weights²).
  /// Throws InvalidArgument for no weights, a non-finite entry, bounds of the wrong size,
  /// non-finite bounds, lower > upper or a negative or non-finite ridge.
  BoundedLeastSquares(const Eigen::Ref<const Eigen::MatrixXd>& a,
                      const Eigen::Ref<const Eigen::VectorXd>& lower,
                      const Eigen::Ref<const Eigen::VectorXd>& upper, double ridge = 0.0);

  [[nodiscard]] Eigen::Index weightCount() const { return m_gram.rows(); }
  [[nodiscard]] Eigen::Index equationCount() const { return m_a.rows(); }

  /// The constrained minimiser for `b` (#equations). Starts from all weights at the lower bound
  /// (or from `start`, clamped, e.g. the previous frame's solution). The Cholesky factor of the
  /// free weights' block is built once per solve, O(#free³), and then updated as weights bind or
  /// are freed, O(#free²) each, so an active-set step costs O(#free · #weights). Total
  /// O(#equations · #weights + #weights³ + steps · #weights²).
  /// Throws InvalidArgument when `b` has the wrong size or a non-finite entry.
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::Ref<const Eigen::VectorXd>& b,
                                      const Eigen::VectorXd* start = nullptr) const;

  /// The same from Aᵀb directly, when the caller has it. O(#weights³ + steps · #weights²).
  [[nodiscard]] Eigen::VectorXd solveNormal(const Eigen::Ref<const Eigen::VectorXd>& atb,
                                            const Eigen::VectorXd* start = nullptr) const;

  /// The memory a solve works in. With a handful of weights, allocating it costs more than the
  /// arithmetic (and far more under AddressSanitizer), so a loop over frames keeps one and passes
  /// it to every solve. One per thread; its contents between calls mean nothing.
  class Workspace
  {
    friend class BoundedLeastSquares;
    Eigen::MatrixXd factor;              // upper-triangular factor of the free weights' block
    std::vector<Eigen::Index> order;     // the free weights, in the order they entered
    std::vector<std::uint8_t> state;     // per weight: free, at the lower or at the upper bound
    Eigen::VectorXd z, fixed, gradient;  // step, bound weights' values, gradient
    std::vector<std::size_t> bound;      // free positions that reached a bound in a step
  };
  /// solveNormal() in `workspace`, allocating nothing once the workspace has served a problem of
  /// this size. `w` is the start when `warmStart` (clamped into the box; e.g. the previous
  /// frame's solution), else it is set to the lower bounds first; it receives the minimiser.
  void solveNormal(const Eigen::Ref<const Eigen::VectorXd>& atb, Eigen::VectorXd& w, bool warmStart,
                   Workspace& workspace) const;

private:
  Eigen::MatrixXd m_a;
  Eigen::MatrixXd m_gram;  // AᵀA + ridge
  Eigen::VectorXd m_lower;
  Eigen::VectorXd m_upper;
};

/// One-off form: BoundedLeastSquares(a, lower, upper).solve(b).
[[nodiscard]] Eigen::VectorXd solveBoundedLeastSquares(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                                       const Eigen::Ref<const Eigen::VectorXd>& b,
                                                       const Eigen::Ref<const Eigen::VectorXd>& lower,
                                                       const Eigen::Ref<const Eigen::VectorXd>& upper);

} // namespace mocap
