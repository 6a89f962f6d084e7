#include "mocap/math/bounded_least_squares.h"

#include "mocap/base/error.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace mocap {

namespace {

enum class Bound : std::uint8_t
{
  Free,
  Lower,
  Upper
};

/// The Cholesky factor RᵀR of H restricted to the free weights, kept as weights leave and enter
/// the free set: removing one is a column deletion restored by Givens rotations, adding one a
/// new column by forward substitution, each O(#free²) where refactorising costs O(#free³). The
/// free weights are kept in the order they entered (order()).
class FreeFactor
{
public:
  /// Starts with no free weight, in the caller's memory `r` and `order` (reused across solves).
  FreeFactor(const Eigen::MatrixXd& h, Eigen::MatrixXd& r, std::vector<Eigen::Index>& order)
      : m_h(h), m_r(r), m_order(order)
  {
    m_r.resize(h.rows(), h.rows());  // no reallocation when the size is unchanged
    m_order.clear();
    m_order.reserve(static_cast<std::size_t>(h.rows()));
  }

  [[nodiscard]] const std::vector<Eigen::Index>& order() const { return m_order; }

  void add(Eigen::Index weight)
  {
    const auto n = static_cast<Eigen::Index>(m_order.size());
    auto column = m_r.col(n).head(n);
    for (Eigen::Index a = 0; a < n; ++a)
      column(a) = m_h(m_order[static_cast<std::size_t>(a)], weight);
    m_r.topLeftCorner(n, n).triangularView<Eigen::Upper>().transpose().solveInPlace(column);
    // A numerically semi-definite H (fewer measurements than weights) gets the smallest pivot
    // that keeps R invertible: the ridge the constructor adds, in effect, once more.
    const double pivot = m_h(weight, weight) - column.squaredNorm();
    m_r(n, n) = std::sqrt(std::max(pivot, 1e-12 * std::max(m_h(weight, weight), 1e-300)));
    m_order.push_back(weight);
  }

  /// Removes the weight at `position` of order().
  void remove(std::size_t position)
  {
    const auto n = static_cast<Eigen::Index>(m_order.size());
    const auto p = static_cast<Eigen::Index>(position);
    for (Eigen::Index j = p; j + 1 < n; ++j)
      m_r.col(j).head(j + 2) = m_r.col(j + 1).head(j + 2);
    for (Eigen::Index i = p; i + 1 < n; ++i) {  // zero the subdiagonal the deletion left
      const double a = m_r(i, i), b = m_r(i + 1, i), r = std::sqrt(a * a + b * b);  // R's scale: no overflow
      const double c = r > 0.0 ? a / r : 1.0, s = r > 0.0 ? b / r : 0.0;
      for (Eigen::Index j = i; j + 1 < n; ++j) {
        const double top = m_r(i, j), bottom = m_r(i + 1, j);
        m_r(i, j) = c * top + s * bottom;
        m_r(i + 1, j) = -s * top + c * bottom;
      }
    }
    m_order.erase(m_order.begin() + static_cast<std::ptrdiff_t>(position));
  }

  /// Solves H_FF·z = rhs in place (#free values, in order()). O(#free²).
  void solve(Eigen::Ref<Eigen::VectorXd> z) const
  {
    const auto n = static_cast<Eigen::Index>(m_order.size());
    const auto r = m_r.topLeftCorner(n, n).triangularView<Eigen::Upper>();
    r.transpose().solveInPlace(z);
    r.solveInPlace(z);
  }

private:
  const Eigen::MatrixXd& m_h;
  Eigen::MatrixXd& m_r;  // the top-left #free² upper triangle is R
  std::vector<Eigen::Index>& m_order;
};

} // namespace

BoundedLeastSquares::BoundedLeastSquares(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                         const Eigen::Ref<const Eigen::VectorXd>& lower,
                                         const Eigen::Ref<const Eigen::VectorXd>& upper, double ridge)
    : m_a(a), m_lower(lower), m_upper(upper)
{
  const Eigen::Index k = a.cols();
  if (k < 1)
    throw InvalidArgument("bounded least squares needs at least one weight");
  if (lower.size() != k || upper.size() != k)
    throw InvalidArgument("bounded least squares: " + std::to_string(k) + " weights but " +
                          std::to_string(lower.size()) + " lower and " + std::to_string(upper.size()) +
                          " upper bounds");
  if (!a.allFinite())
    throw InvalidArgument("bounded least squares: the matrix has a non-finite entry");
  if (!lower.allFinite() || !upper.allFinite())
    throw InvalidArgument("bounded least squares: the bounds must be finite");
  if ((lower.array() > upper.array()).any())
    throw InvalidArgument("bounded least squares: a lower bound exceeds its upper bound");
  if (!(ridge >= 0.0) || !std::isfinite(ridge))
    throw InvalidArgument("bounded least squares: the ridge must be finite and ≥ 0");
  m_gram = a.transpose() * a;
  const double leastNorm = 1e-12 * std::max(m_gram.trace() / static_cast<double>(k), 1e-300);
  m_gram.diagonal().array() += leastNorm + ridge;
}

Eigen::VectorXd BoundedLeastSquares::solve(const Eigen::Ref<const Eigen::VectorXd>& b,
                                           const Eigen::VectorXd* start) const
{
  if (b.size() != m_a.rows())
    throw InvalidArgument("bounded least squares: expected " + std::to_string(m_a.rows()) + " values, got " +
                          std::to_string(b.size()));
  if (!b.allFinite())
    throw InvalidArgument("bounded least squares: the right-hand side has a non-finite entry");
  return solveNormal(m_a.transpose() * b, start);
}

Eigen::VectorXd BoundedLeastSquares::solveNormal(const Eigen::Ref<const Eigen::VectorXd>& atb,
                                                 const Eigen::VectorXd* start) const
{
  if (start && start->size() != weightCount())
    throw InvalidArgument("bounded least squares: the start has the wrong size");
  Workspace workspace;
  Eigen::VectorXd w = start ? *start : Eigen::VectorXd();
  solveNormal(atb, w, start != nullptr, workspace);
  return w;
}

void BoundedLeastSquares::solveNormal(const Eigen::Ref<const Eigen::VectorXd>& atb, Eigen::VectorXd& w,
                                      bool warmStart, Workspace& workspace) const
{
  const Eigen::Index k = weightCount();
  if (atb.size() != k || !atb.allFinite())
    throw InvalidArgument("bounded least squares: Aᵀb must hold " + std::to_string(k) + " finite values");
  if (warmStart && w.size() != k)
    throw InvalidArgument("bounded least squares: the start has the wrong size");

  // Minimise ½wᵀHw − gᵀw over the box; every iterate is feasible.
  const Eigen::MatrixXd& h = m_gram;
  std::vector<std::uint8_t>& state = workspace.state;
  const auto stateOf = [&](Eigen::Index i) -> Bound { return static_cast<Bound>(state[static_cast<std::size_t>(i)]); };
  const auto setState = [&](Eigen::Index i, Bound b) { state[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(b); };
  state.assign(static_cast<std::size_t>(k), static_cast<std::uint8_t>(Bound::Lower));
  if (warmStart) {
    w = w.cwiseMax(m_lower).cwiseMin(m_upper);
    for (Eigen::Index i = 0; i < k; ++i)
      setState(i, w(i) <= m_lower(i) ? Bound::Lower : (w(i) >= m_upper(i) ? Bound::Upper : Bound::Free));
  } else {
    w = m_lower;
  }
  const double boundScale = std::max(m_lower.cwiseAbs().maxCoeff(), m_upper.cwiseAbs().maxCoeff());
  const double tolerance = 1e-11 * std::max({atb.cwiseAbs().maxCoeff(),
                                             h.cwiseAbs().maxCoeff() * std::max(boundScale, 1.0), 1e-300});
  const int maxSteps = 10 * static_cast<int>(k) + 20;

  FreeFactor factor(h, workspace.factor, workspace.order);  // kept up to date, not redone each step
  for (Eigen::Index i = 0; i < k; ++i)
    if (stateOf(i) == Bound::Free)
      factor.add(i);
  Eigen::VectorXd& z = workspace.z;
  Eigen::VectorXd& fixed = workspace.fixed;
  Eigen::VectorXd& gradient = workspace.gradient;
  z.resize(k);
  fixed.resize(k);
  gradient.resize(k);
  std::vector<std::size_t>& bound = workspace.bound;
  bound.reserve(static_cast<std::size_t>(k));
  for (int step = 0; step < maxSteps; ++step) {
    // Make the free weights optimal with the bound ones held, stepping back to the box when the
    // optimum leaves it and binding the weight that blocked the step.
    while (true) {
      const std::vector<Eigen::Index>& freeSet = factor.order();
      if (freeSet.empty())
        break;
      const auto nf = static_cast<Eigen::Index>(freeSet.size());
      for (Eigen::Index i = 0; i < k; ++i)
        fixed(i) = stateOf(i) == Bound::Free ? 0.0 : w(i);
      for (Eigen::Index a = 0; a < nf; ++a)
        z(a) = atb(freeSet[static_cast<std::size_t>(a)]) - h.col(freeSet[static_cast<std::size_t>(a)]).dot(fixed);  // H symmetric: a contiguous column
      factor.solve(z.head(nf));
      double alpha = 1.0;
      Eigen::Index blocking = -1;
      for (Eigen::Index j = 0; j < nf; ++j) {
        const Eigen::Index i = freeSet[static_cast<std::size_t>(j)];
        double t = 1.0;
        if (z(j) < m_lower(i))
          t = (m_lower(i) - w(i)) / (z(j) - w(i));
        else if (z(j) > m_upper(i))
          t = (m_upper(i) - w(i)) / (z(j) - w(i));
        else
          continue;
        t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
        if (blocking < 0 || t < alpha) {
          alpha = t;
          blocking = j;
        }
      }
      if (blocking < 0) {
        for (Eigen::Index j = 0; j < nf; ++j)
          w(freeSet[static_cast<std::size_t>(j)]) = z(j);
        break;
      }
      bound.clear();
      for (Eigen::Index j = 0; j < nf; ++j) {
        const Eigen::Index i = freeSet[static_cast<std::size_t>(j)];
        w(i) = std::clamp(w(i) + alpha * (z(j) - w(i)), m_lower(i), m_upper(i));
        const double span = 1e-14 * std::max(1.0, m_upper(i) - m_lower(i));
        const bool hitLower = z(j) < m_lower(i) && (j == blocking || w(i) <= m_lower(i) + span);
        const bool hitUpper = z(j) > m_upper(i) && (j == blocking || w(i) >= m_upper(i) - span);
        if (hitLower) {
          w(i) = m_lower(i);
          setState(i, Bound::Lower);
          bound.push_back(static_cast<std::size_t>(j));
        } else if (hitUpper) {
          w(i) = m_upper(i);
          setState(i, Bound::Upper);
          bound.push_back(static_cast<std::size_t>(j));
        }
      }
      for (auto position = bound.rbegin(); position != bound.rend(); ++position)
        factor.remove(*position);  // from the back, so the earlier positions stay valid
      if (++step >= maxSteps)
        return;
    }
    // KKT: every bound weight whose gradient points into the box is freed at once (freeing one
    // per step, as Lawson & Hanson do, costs a factorisation per weight that enters). The
    // subspace step that follows starts from a feasible point, so the objective still decreases.
    gradient.noalias() = h * w;
    gradient -= atb;
    bool freed = false;
    for (Eigen::Index i = 0; i < k; ++i) {
      const Bound s = stateOf(i);
      if (s == Bound::Free || m_lower(i) == m_upper(i))
        continue;
      const double violation = s == Bound::Lower ? -gradient(i) : gradient(i);
      if (violation > tolerance) {
        setState(i, Bound::Free);
        factor.add(i);
        freed = true;
      }
    }
    if (!freed)
      return;
  }
}

Eigen::VectorXd solveBoundedLeastSquares(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                         const Eigen::Ref<const Eigen::VectorXd>& b,
                                         const Eigen::Ref<const Eigen::VectorXd>& lower,
                                         const Eigen::Ref<const Eigen::VectorXd>& upper)
{
  return BoundedLeastSquares(a, lower, upper).solve(b);
}

} // namespace mocap
