#include "mocap/math/hungarian_assignment.h"

#include "mocap/base/error.h"
#include "mocap/math/union_find.h"

#include <cmath>

namespace mocap {

namespace {

void checkInput(const Eigen::Ref<const Eigen::MatrixXd>& cost, double gate)
{
  if (std::isnan(gate) || gate < 0.0)
    throw InvalidArgument("assignment: the gate must be a number ≥ 0");
  if (!cost.allFinite() || (cost.size() > 0 && cost.minCoeff() < 0.0))
    throw InvalidArgument("assignment: every cost must be finite and ≥ 0");
}


// Hungarian method with potentials on a dense n × m matrix, n ≤ m: the column of each row.
// O(n² · m).
std::vector<Eigen::Index> solveDense(const Eigen::MatrixXd& a)
{
  const Eigen::Index n = a.rows();
  const Eigen::Index m = a.cols();
  const double inf = std::numeric_limits<double>::infinity();
  // 1-based as in the classic formulation: column 0 is the virtual start, p[j] the row of column j.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n + 1);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(m + 1);
  std::vector<Eigen::Index> p(static_cast<std::size_t>(m + 1), 0);
  std::vector<Eigen::Index> way(static_cast<std::size_t>(m + 1), 0);
  std::vector<double> minv(static_cast<std::size_t>(m + 1));
  std::vector<char> used(static_cast<std::size_t>(m + 1));
  const auto at = [](auto& vec, Eigen::Index i) -> auto& { return vec[static_cast<std::size_t>(i)]; };
  for (Eigen::Index i = 1; i <= n; ++i) {
    at(p, 0) = i;
    Eigen::Index j0 = 0;
    std::fill(minv.begin(), minv.end(), inf);
    std::fill(used.begin(), used.end(), char{0});
    do {
      at(used, j0) = 1;
      const Eigen::Index i0 = at(p, j0);
      double delta = inf;
      Eigen::Index j1 = 0;
      for (Eigen::Index j = 1; j <= m; ++j) {
        if (at(used, j))
          continue;
        const double reduced = a(i0 - 1, j - 1) - u(i0) - v(j);
        if (reduced < at(minv, j)) {
          at(minv, j) = reduced;
          at(way, j) = j0;
        }
        if (at(minv, j) < delta) {
          delta = at(minv, j);
          j1 = j;
        }
      }
      for (Eigen::Index j = 0; j <= m; ++j) {
        if (at(used, j)) {
          u(at(p, j)) += delta;
          v(j) -= delta;
        } else {
          at(minv, j) -= delta;
        }
      }
      j0 = j1;
    } while (at(p, j0) != 0);
    do {
      const Eigen::Index j1 = at(way, j0);
      at(p, j0) = at(p, j1);
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<Eigen::Index> column(static_cast<std::size_t>(n), kUnassigned);
  for (Eigen::Index j = 1; j <= m; ++j)
    if (at(p, j) != 0)
      column[static_cast<std::size_t>(at(p, j) - 1)] = j - 1;
  return column;
}

// One component: rows × (cols + one private "unassigned" column per row), pairs over the gate
// forbidden by a cost above the all-unassigned solution.
void solveComponent(const Eigen::Ref<const Eigen::MatrixXd>& cost, double gate, const std::vector<Eigen::Index>& rows,
                    const std::vector<Eigen::Index>& cols, std::vector<Eigen::Index>& result)
{
  const auto n = static_cast<Eigen::Index>(rows.size());
  const auto m = static_cast<Eigen::Index>(cols.size());
  const double forbidden = gate * static_cast<double>(n + 1) + 1.0;
  Eigen::MatrixXd padded = Eigen::MatrixXd::Constant(n, m + n, forbidden);
  for (Eigen::Index r = 0; r < n; ++r) {
    for (Eigen::Index c = 0; c < m; ++c) {
      const double value = cost(rows[static_cast<std::size_t>(r)], cols[static_cast<std::size_t>(c)]);
      if (value <= gate)
        padded(r, c) = value;
    }
    padded(r, m + r) = gate;
  }
  const std::vector<Eigen::Index> column = solveDense(padded);
  for (Eigen::Index r = 0; r < n; ++r) {
    const Eigen::Index c = column[static_cast<std::size_t>(r)];
    if (c >= 0 && c < m)
      result[static_cast<std::size_t>(rows[static_cast<std::size_t>(r)])] = cols[static_cast<std::size_t>(c)];
  }
}

} // namespace

std::vector<Eigen::Index> assignMinimumCost(const Eigen::Ref<const Eigen::MatrixXd>& cost, double gate)
{
  checkInput(cost, gate);
  const Eigen::Index n = cost.rows();
  const Eigen::Index m = cost.cols();
  std::vector<Eigen::Index> result(static_cast<std::size_t>(n), kUnassigned);
  if (n == 0 || m == 0)
    return result;
  if (std::isinf(gate))  // above any solution with one more row unassigned: maximum cardinality first
    gate = (cost.maxCoeff() + 1.0) * static_cast<double>(std::min(n, m) + 1);
  UnionFind components(n + m);
  for (Eigen::Index c = 0; c < m; ++c)
    for (Eigen::Index r = 0; r < n; ++r)
      if (cost(r, c) <= gate)
        components.unite(r, n + c);
  std::vector<std::vector<Eigen::Index>> rowsOf(static_cast<std::size_t>(n + m));
  std::vector<std::vector<Eigen::Index>> colsOf(static_cast<std::size_t>(n + m));
  for (Eigen::Index r = 0; r < n; ++r)
    rowsOf[static_cast<std::size_t>(components.find(r))].push_back(r);
  for (Eigen::Index c = 0; c < m; ++c)
    colsOf[static_cast<std::size_t>(components.find(n + c))].push_back(c);
  for (std::size_t k = 0; k < rowsOf.size(); ++k) {
    const auto& rows = rowsOf[k];
    const auto& cols = colsOf[k];
    if (rows.empty() || cols.empty())
      continue;
    if (rows.size() == 1 && cols.size() == 1)
      result[static_cast<std::size_t>(rows[0])] = cols[0];  // united only through a gated pair
    else
      solveComponent(cost, gate, rows, cols, result);
  }
  return result;
}

double assignmentCost(const Eigen::Ref<const Eigen::MatrixXd>& cost, const std::vector<Eigen::Index>& assignment)
{
  if (static_cast<Eigen::Index>(assignment.size()) != cost.rows())
    throw InvalidArgument("assignment cost: one column per row expected");
  double total = 0.0;
  for (Eigen::Index r = 0; r < cost.rows(); ++r) {
    const Eigen::Index c = assignment[static_cast<std::size_t>(r)];
    if (c == kUnassigned)
      continue;
    if (c < 0 || c >= cost.cols())
      throw InvalidArgument("assignment cost: column out of range");
    total += cost(r, c);
  }
  return total;
}

} // namespace mocap
