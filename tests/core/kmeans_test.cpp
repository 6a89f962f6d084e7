// PCA and k-means, the two halves of Principal Feature Analysis.
#include "mocap/base/error.h"
#include "mocap/math/kmeans.h"
#include "mocap/math/pca.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <random>
#include <set>

namespace mocap {
namespace {

TEST(Pca, KeepsTheFewestComponentsReachingTheVarianceFraction)
{
  std::mt19937 random(2);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd data(500, 4);
  for (Eigen::Index i = 0; i < data.rows(); ++i) {
    const double t = normal(random);
    data.row(i) << 10.0 * t, -5.0 * t + 0.1 * normal(random), 0.1 * normal(random),
        2.0 + 0.1 * normal(random);
  }
  const PrincipalComponents one = computePca(data, 0.98);
  ASSERT_EQ(one.count(), 1);
  EXPECT_GE(one.explainedFraction(), 0.98);
  EXPECT_NEAR(std::abs(one.components(0, 0)), 2.0 / std::sqrt(5.0), 1e-2);
  EXPECT_GT(one.components.col(0).cwiseAbs().maxCoeff(), 0.0);
  const PrincipalComponents all = computePca(data, 1.0);
  ASSERT_EQ(all.count(), 4);
  EXPECT_NEAR((all.components.transpose() * all.components - Eigen::MatrixXd::Identity(4, 4)).norm(), 0.0,
              1e-12);
  EXPECT_TRUE(std::is_sorted(all.variances.data(), all.variances.data() + 4, std::greater<double>()));
}

TEST(Pca, BadInputThrows)
{
  EXPECT_THROW((void)computePca(Eigen::MatrixXd::Ones(1, 3), 0.9), InvalidArgument);
  EXPECT_THROW((void)computePca(Eigen::MatrixXd::Random(5, 3), 0.0), InvalidArgument);
  EXPECT_THROW((void)computePca(Eigen::MatrixXd::Ones(5, 3), 0.9), InvalidArgument);  // no variance
  Eigen::MatrixXd withNan = Eigen::MatrixXd::Random(5, 3);
  withNan(2, 2) = std::nan("");
  EXPECT_THROW((void)computePca(withNan, 0.9), InvalidArgument);
}

TEST(KMeans, RecoversSeparatedBlobsAndPicksAMemberOfEach)
{
  std::mt19937 random(4);
  std::normal_distribution<double> normal(0.0, 0.1);
  const Eigen::MatrixXd centres = (Eigen::MatrixXd(3, 2) << 0, 0, 10, 0, 0, 10).finished();
  Eigen::MatrixXd points(90, 2);
  for (Eigen::Index i = 0; i < 90; ++i)
    points.row(i) = centres.row(i % 3) + Eigen::RowVector2d(normal(random), normal(random));
  const KMeansPoints prepared(points);
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const KMeansResult result = kMeans(prepared, 3, seed);
    std::set<Eigen::Index> blobs;
    for (Eigen::Index i = 0; i < 90; ++i)
      EXPECT_EQ(result.assignment[static_cast<std::size_t>(i)],
                result.assignment[static_cast<std::size_t>(i % 3)]);
    for (const Eigen::Index r : result.representatives) {
      ASSERT_GE(r, 0);
      blobs.insert(r % 3);
    }
    EXPECT_EQ(blobs.size(), 3u);
    EXPECT_LT(result.inertia, 90 * 0.1);
  }
  EXPECT_EQ(kMeans(prepared, 5, 7).assignment, kMeans(prepared, 5, 7).assignment);
  EXPECT_NE(mixSeed(1, 5, 0), mixSeed(1, 5, 1));
}

TEST(KMeans, BadInputThrows)
{
  const KMeansPoints points(Eigen::MatrixXd::Random(4, 2));
  EXPECT_THROW((void)kMeans(points, 5, 1), InvalidArgument);
  EXPECT_THROW((void)kMeans(points, 0, 1), InvalidArgument);
  EXPECT_THROW(KMeansPoints(Eigen::MatrixXd(0, 2)), InvalidArgument);
}

} // namespace
} // namespace mocap
