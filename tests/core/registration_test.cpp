#include "mocap/math/registration.h"

#include "mocap/base/error.h"
#include "mocap/base/random.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

namespace mocap {
namespace {

PointSet randomPoints(Eigen::Index count, std::uint64_t seed)
{
  Random random(seed);
  PointSet points(count, 3);
  for (Eigen::Index i = 0; i < count; ++i)
    points.row(i) = Eigen::RowVector3d(40.0 * random.normal(), 25.0 * random.normal(), 10.0 * random.normal());
  return points;
}

Similarity someSimilarity()
{
  Similarity s;
  s.rotation = Eigen::AngleAxisd(0.2, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  s.scale = 1.3;
  s.translation = Eigen::Vector3d(5, -7, 12);
  return s;
}

void expectNear(const Similarity& a, const Similarity& b, double tolerance)
{
  EXPECT_NEAR((a.rotation - b.rotation).norm(), 0.0, tolerance);
  EXPECT_NEAR(a.scale, b.scale, tolerance);
  EXPECT_NEAR((a.translation - b.translation).norm(), 0.0, 100.0 * tolerance);
}

TEST(Registration, SimilarityThroughTakesOneCentreOntoTheOther)
{
  const Similarity s = similarityThrough(someSimilarity().rotation, 2.0, Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-4, 0, 9));
  EXPECT_NEAR((s.apply(Eigen::Vector3d(1, 2, 3)) - Eigen::Vector3d(-4, 0, 9)).norm(), 0.0, 1e-12);
  EXPECT_EQ(s.scale, 2.0);
}

TEST(Registration, PrincipalFrameIsRightHandedWithTheLargestSpreadFirst)
{
  const PointSet points = randomPoints(500, 3);
  const PrincipalFrame frame = principalFrame(points);
  EXPECT_NEAR(frame.axes.determinant(), 1.0, 1e-12);
  EXPECT_GT(std::abs(frame.axes(0, 0)), 0.9);  // x spread 40, then y 25, then z 10
  EXPECT_GT(std::abs(frame.axes(1, 1)), 0.9);
  EXPECT_NEAR((frame.centre.transpose() - points.colwise().mean()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(frame.radius, std::sqrt((points.rowwise() - points.colwise().mean()).rowwise().squaredNorm().mean()),
              1e-12);
}

TEST(Registration, IcpPairingEachSourceRecoversASimilarityFromNearby)
{
  const PointSet source = randomPoints(60, 5);
  const Similarity truth = someSimilarity();
  const PointSet target = truth.applyToRows(source);
  Similarity start = truth;
  start.rotation = Eigen::AngleAxisd(0.03, Eigen::Vector3d::UnitZ()).toRotationMatrix() * truth.rotation;
  start.translation += Eigen::Vector3d(1.0, -0.5, 0.3);
  IcpOptions options;
  options.errorTolerance = 1e-9;
  const IcpResult result = icp(source, target, start, options);
  expectNear(result.transform, truth, 1e-6);
  EXPECT_LT(result.rms, 1e-6);
  EXPECT_LT(closestPointDistances(source, target, result.transform, options).maxCoeff(), 1e-6);
}

TEST(Registration, IcpClampsTheScale)
{
  const PointSet source = randomPoints(60, 6);
  const Similarity truth = someSimilarity();
  const PointSet target = truth.applyToRows(source);
  Similarity start = truth;
  start.scale = 1.0;
  start.translation = truth.translation;
  IcpOptions options;
  options.errorTolerance = 1e-9;
  options.maxScale = 1.1;
  const IcpResult result = icp(source, target, start, options);
  EXPECT_LE(result.transform.scale, 1.1);  // the unclamped fit would reach 1.3
  EXPECT_GT(result.rms, 0.0);
}

TEST(Registration, IcpPairingEachTargetIgnoresMissingPointsAndTrimsStrays)
{
  const PointSet source = randomPoints(40, 7);
  const Similarity truth = someSimilarity();
  PointSet target(33, 3);
  target.topRows(30) = truth.applyToRows(source.topRows(30));   // ten source points missing
  target.row(30) = Eigen::RowVector3d(400, 400, 400);           // three strays far away
  target.row(31) = Eigen::RowVector3d(-400, 300, 0);
  target.row(32) = Eigen::RowVector3d(0, -500, 200);
  Similarity start = truth;
  start.translation += Eigen::Vector3d(0.5, 0.5, -0.5);
  IcpOptions options;
  options.pairing = IcpPairing::EachTarget;
  options.inlierFactor = 2.5;
  options.changeTolerance = 1e-10;
  const IcpResult result = icp(source, target, start, options);
  expectNear(result.transform, truth, 1e-6);
  const Eigen::VectorXd distances = closestPointDistances(source, target, result.transform, options);
  ASSERT_EQ(distances.size(), target.rows());
  EXPECT_LT(distances.head(30).maxCoeff(), 1e-6);
  EXPECT_GT(distances.tail(3).minCoeff(), 100.0);
}

TEST(Registration, IcpRejectsEmptyOrNonFinitePoints)
{
  const PointSet points = randomPoints(5, 1);
  EXPECT_THROW(static_cast<void>(icp(PointSet(0, 3), points, {}, {})), InvalidArgument);
  EXPECT_THROW(static_cast<void>(icp(points, PointSet(0, 3), {}, {})), InvalidArgument);
  PointSet bad = points;
  bad(2, 1) = std::nan("");
  EXPECT_THROW(static_cast<void>(icp(bad, points, {}, {})), InvalidArgument);
}

} // namespace
} // namespace mocap
