#include "mocap/base/error.h"
#include "mocap/math/hungarian_assignment.h"
#include "mocap/base/random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace mocap {
namespace {

// Σ assigned cost + gate · unassigned rows.
double objective(const Eigen::MatrixXd& cost, const std::vector<Eigen::Index>& assignment, double gate)
{
  double total = 0.0;
  for (Eigen::Index r = 0; r < cost.rows(); ++r) {
    const Eigen::Index c = assignment[static_cast<std::size_t>(r)];
    total += c == kUnassigned ? gate : cost(r, c);
  }
  return total;
}

// The best objective over every partial assignment respecting the gate (exhaustive).
double bruteForce(const Eigen::MatrixXd& cost, double gate, Eigen::Index row, std::vector<bool>& used)
{
  if (row == cost.rows())
    return 0.0;
  double best = gate + bruteForce(cost, gate, row + 1, used);
  for (Eigen::Index c = 0; c < cost.cols(); ++c) {
    if (used[static_cast<std::size_t>(c)] || cost(row, c) > gate)
      continue;
    used[static_cast<std::size_t>(c)] = true;
    best = std::min(best, cost(row, c) + bruteForce(cost, gate, row + 1, used));
    used[static_cast<std::size_t>(c)] = false;
  }
  return best;
}

void expectValid(const Eigen::MatrixXd& cost, const std::vector<Eigen::Index>& assignment, double gate)
{
  ASSERT_EQ(static_cast<Eigen::Index>(assignment.size()), cost.rows());
  std::set<Eigen::Index> columns;
  for (Eigen::Index r = 0; r < cost.rows(); ++r) {
    const Eigen::Index c = assignment[static_cast<std::size_t>(r)];
    if (c == kUnassigned)
      continue;
    ASSERT_GE(c, 0);
    ASSERT_LT(c, cost.cols());
    EXPECT_TRUE(columns.insert(c).second) << "column " << c << " used twice";
    EXPECT_LE(cost(r, c), gate);
  }
}

TEST(HungarianAssignment, MatchesExhaustiveSearchOnRandomGatedProblems)
{
  Random random(7);
  for (int trial = 0; trial < 300; ++trial) {
    const auto rows = static_cast<Eigen::Index>(1 + random.uniform() * 6);
    const auto cols = static_cast<Eigen::Index>(1 + random.uniform() * 6);
    Eigen::MatrixXd cost(rows, cols);
    for (Eigen::Index i = 0; i < cost.size(); ++i)
      cost(i) = std::floor(random.uniform() * 20.0);
    const double gate = trial % 3 == 0 ? 25.0 : 2.0 + std::floor(random.uniform() * 12.0);
    const std::vector<Eigen::Index> assignment = assignMinimumCost(cost, gate);
    expectValid(cost, assignment, gate);
    std::vector<bool> used(static_cast<std::size_t>(cols), false);
    EXPECT_NEAR(objective(cost, assignment, gate), bruteForce(cost, gate, 0, used), 1e-9)
        << "trial " << trial << "\n" << cost;
  }
}

TEST(HungarianAssignment, InfiniteGateAssignsAsManyRowsAsPossibleAtLeastCost)
{
  Eigen::MatrixXd cost(3, 2);
  cost << 1, 100, 2, 100, 50, 3;
  const auto assignment = assignMinimumCost(cost);
  const auto assigned = std::count_if(assignment.begin(), assignment.end(), [](Eigen::Index c) { return c >= 0; });
  EXPECT_EQ(assigned, 2);
  // Rows 0 and 1 compete for column 0 (row 0 is cheaper); row 2 takes column 1.
  EXPECT_EQ(assignment[0], 0);
  EXPECT_EQ(assignment[2], 1);
  EXPECT_EQ(assignmentCost(cost, assignment), 4.0);
}

TEST(HungarianAssignment, GateLeavesFarPairsUnassigned)
{
  Eigen::MatrixXd cost(2, 2);
  cost << 1, 9, 9, 9;
  const auto assignment = assignMinimumCost(cost, 5.0);
  EXPECT_EQ(assignment[0], 0);
  EXPECT_EQ(assignment[1], kUnassigned);
}

TEST(HungarianAssignment, EmptyProblemsAndBadInput)
{
  EXPECT_EQ(assignMinimumCost(Eigen::MatrixXd(0, 4)).size(), 0U);
  EXPECT_EQ(assignMinimumCost(Eigen::MatrixXd(3, 0)), std::vector<Eigen::Index>(3, kUnassigned));
  Eigen::MatrixXd cost = Eigen::MatrixXd::Ones(2, 2);
  EXPECT_THROW((void)assignMinimumCost(cost, -1.0), InvalidArgument);
  EXPECT_THROW((void)assignMinimumCost(cost, std::nan("")), InvalidArgument);
  cost(1, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)assignMinimumCost(cost), InvalidArgument);
  cost(1, 1) = -1.0;
  EXPECT_THROW((void)assignMinimumCost(cost), InvalidArgument);
}

} // namespace
} // namespace mocap
