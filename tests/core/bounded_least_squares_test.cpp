// Bounded least squares (blendshape weights in [0, 1]): bounds, optimality, interior agreement.
#include "mocap/math/bounded_least_squares.h"
#include "mocap/base/error.h"

#include <Eigen/QR>
#include <gtest/gtest.h>

#include <random>

namespace mocap {
namespace {

Eigen::MatrixXd randomMatrix(Eigen::Index rows, Eigen::Index cols, unsigned seed)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  return Eigen::MatrixXd::NullaryExpr(rows, cols, [&] { return normal(random); });
}

// KKT conditions of min ½‖Aw − b‖² on the box: a free weight has zero gradient, a weight at its
// lower bound a gradient ≥ 0, at its upper bound ≤ 0.
void expectOptimal(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, const Eigen::VectorXd& w,
                   const Eigen::VectorXd& lower, const Eigen::VectorXd& upper)
{
  const Eigen::VectorXd gradient = a.transpose() * (a * w - b);
  const double tolerance = 1e-8 * (1.0 + (a.transpose() * b).cwiseAbs().maxCoeff());
  for (Eigen::Index i = 0; i < w.size(); ++i) {
    ASSERT_GE(w(i), lower(i));
    ASSERT_LE(w(i), upper(i));
    if (lower(i) == upper(i))
      continue;  // a fixed weight may have any gradient
    if (w(i) > lower(i) && w(i) < upper(i))
      EXPECT_NEAR(gradient(i), 0.0, tolerance) << i;
    else if (w(i) == lower(i))
      EXPECT_GE(gradient(i), -tolerance) << i;
    else
      EXPECT_LE(gradient(i), tolerance) << i;
  }
}

TEST(BoundedLeastSquares, RespectsTheBoundsAndIsOptimal)
{
  const Eigen::VectorXd lower = Eigen::VectorXd::Zero(8), upper = Eigen::VectorXd::Ones(8);
  for (unsigned seed = 0; seed < 50; ++seed) {
    const Eigen::MatrixXd a = randomMatrix(20, 8, seed);
    const Eigen::VectorXd b = 3.0 * randomMatrix(20, 1, seed + 100);
    const Eigen::VectorXd w = solveBoundedLeastSquares(a, b, lower, upper);
    expectOptimal(a, b, w, lower, upper);
  }
}

TEST(BoundedLeastSquares, MatchesTheUnconstrainedSolveWhenTheOptimumIsInterior)
{
  for (unsigned seed = 0; seed < 20; ++seed) {
    const Eigen::MatrixXd a = randomMatrix(30, 6, seed);
    const Eigen::VectorXd truth =
        Eigen::VectorXd::Constant(6, 0.5) + 0.3 * randomMatrix(6, 1, seed + 7).cwiseMin(1.0).cwiseMax(-1.0);
    const Eigen::VectorXd b = a * truth + 0.01 * randomMatrix(30, 1, seed + 9);
    const Eigen::VectorXd unconstrained = a.colPivHouseholderQr().solve(b);
    ASSERT_TRUE((unconstrained.array() > 0.0).all() && (unconstrained.array() < 1.0).all());
    const Eigen::VectorXd w =
        solveBoundedLeastSquares(a, b, Eigen::VectorXd::Zero(6), Eigen::VectorXd::Ones(6));
    EXPECT_LT((w - unconstrained).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(BoundedLeastSquares, WarmStartAndGeneralBoundsGiveTheSameOptimum)
{
  const Eigen::MatrixXd a = randomMatrix(12, 5, 4);
  const Eigen::VectorXd lower = (Eigen::VectorXd(5) << -1, 0, 0.2, -3, 0.5).finished();
  const Eigen::VectorXd upper = (Eigen::VectorXd(5) << 1, 0, 0.4, 3, 2).finished();  // weight 1 fixed at 0
  const BoundedLeastSquares solver(a, lower, upper);
  for (unsigned seed = 0; seed < 20; ++seed) {
    const Eigen::VectorXd b = 4.0 * randomMatrix(12, 1, seed + 30);
    const Eigen::VectorXd cold = solver.solve(b);
    const Eigen::VectorXd start = randomMatrix(5, 1, seed + 60);
    const Eigen::VectorXd warm = solver.solve(b, &start);
    expectOptimal(a, b, cold, lower, upper);
    EXPECT_EQ(cold(1), 0.0);
    EXPECT_LT((cold - warm).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(BoundedLeastSquares, MoreWeightsThanEquationsStaysInTheBox)
{
  const Eigen::MatrixXd a = randomMatrix(3, 10, 8);
  const Eigen::VectorXd b = randomMatrix(3, 1, 9);
  const Eigen::VectorXd w =
      solveBoundedLeastSquares(a, b, Eigen::VectorXd::Zero(10), Eigen::VectorXd::Ones(10));
  EXPECT_TRUE((w.array() >= 0.0).all() && (w.array() <= 1.0).all());
  EXPECT_LE((a * w - b).norm(), b.norm() + 1e-12);
}

// As the blendshape solve runs it: correlated columns, weights drifting across both bounds, each
// frame warm-started from the previous, so the free set changes by a few weights at a time (the
// factor is updated, not rebuilt). Every frame must still be the exact optimum.
TEST(BoundedLeastSquares, WarmStartedFramesWithChangingFreeSetsStayOptimal)
{
  const Eigen::Index weights = 40;
  const Eigen::MatrixXd mixing = Eigen::MatrixXd::Identity(weights, weights) + 0.4 * randomMatrix(weights, weights, 3);
  const Eigen::MatrixXd a = randomMatrix(120, weights, 2) * mixing;
  const Eigen::VectorXd lower = Eigen::VectorXd::Zero(weights), upper = Eigen::VectorXd::Ones(weights);
  const BoundedLeastSquares solver(a, lower, upper);
  Eigen::VectorXd truth = Eigen::VectorXd::Constant(weights, 0.5), previous = lower;
  for (unsigned frame = 0; frame < 200; ++frame) {
    truth += 0.15 * randomMatrix(weights, 1, 1000 + frame);  // drifts outside [0, 1] too
    const Eigen::VectorXd b = a * truth + 0.2 * randomMatrix(120, 1, 5000 + frame);
    const Eigen::VectorXd w = solver.solve(b, &previous);
    expectOptimal(a, b, w, lower, upper);
    if (frame % 20 == 0) {
      EXPECT_LT((w - solver.solve(b)).cwiseAbs().maxCoeff(), 1e-8) << frame;  // cold start agrees
    }
    previous = w;
  }
}

TEST(BoundedLeastSquares, BadInputThrows)
{
  const Eigen::MatrixXd a = randomMatrix(4, 2, 1);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(2), one = Eigen::VectorXd::Ones(2);
  EXPECT_THROW(BoundedLeastSquares(a, one, zero), InvalidArgument);
  EXPECT_THROW(BoundedLeastSquares(a, Eigen::VectorXd::Zero(3), one), InvalidArgument);
  Eigen::MatrixXd withNan = a;
  withNan(1, 1) = std::nan("");
  EXPECT_THROW(BoundedLeastSquares(withNan, zero, one), InvalidArgument);
  const BoundedLeastSquares solver(a, zero, one);
  EXPECT_THROW((void)solver.solve(Eigen::VectorXd::Zero(3)), InvalidArgument);
  EXPECT_THROW((void)solver.solve(Eigen::VectorXd::Constant(4, std::nan(""))), InvalidArgument);
}

} // namespace
} // namespace mocap
