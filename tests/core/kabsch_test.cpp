#include "mocap/base/error.h"
#include "mocap/math/kabsch.h"

#include <gtest/gtest.h>

#include <Eigen/SVD>

#include <cmath>
#include <limits>
#include <random>

namespace mocap {
namespace {

Eigen::Isometry3d randomPose(std::mt19937& random)
{
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() =
      Eigen::AngleAxisd(3.0 * normal(random),
                        Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized())
          .toRotationMatrix();
  pose.translation() = 100.0 * Eigen::Vector3d(normal(random), normal(random), normal(random));
  return pose;
}

PointSet randomPoints(std::mt19937& random, Eigen::Index count, const Eigen::Vector3d& scale)
{
  std::normal_distribution<double> normal(0.0, 1.0);
  PointSet points(count, 3);
  for (Eigen::Index i = 0; i < count; ++i)
    points.row(i) =
        Eigen::Vector3d(normal(random), normal(random), normal(random)).cwiseProduct(scale).transpose();
  return points;
}

PointSet transformed(const Eigen::Isometry3d& pose, const PointSet& points)
{
  PointSet out(points.rows(), 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    out.row(i) = (pose * points.row(i).transpose()).transpose();
  return out;
}

// The textbook solution (SVD with the sign correction), the reference for the fast path.
Eigen::Matrix3d referenceRotation(const Eigen::Matrix3d& covariance)
{
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  if ((u * svd.matrixV().transpose()).determinant() < 0.0)
    u.col(2) = -u.col(2);
  return u * svd.matrixV().transpose();
}

TEST(Kabsch, RecoversARigidMotionExactly)
{
  std::mt19937 random(1);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Isometry3d pose = randomPose(random);
    const PointSet from = randomPoints(random, 8, Eigen::Vector3d(50, 40, 30));
    const Eigen::Isometry3d fit = kabsch(from, transformed(pose, from));
    EXPECT_LT((fit.matrix() - pose.matrix()).norm(), 1e-9);
    EXPECT_LT(rigidResidual(fit, from, transformed(pose, from)), 1e-9);
  }
}

TEST(Kabsch, FlatAndNearlyFlatClustersAsFacesAre)
{
  std::mt19937 random(2);
  for (const double thickness : {1.0, 1e-2, 1e-5, 0.0}) {
    const Eigen::Isometry3d pose = randomPose(random);
    const PointSet from = randomPoints(random, 6, Eigen::Vector3d(40, 30, 40 * thickness));
    EXPECT_LT((kabsch(from, transformed(pose, from)).matrix() - pose.matrix()).norm(), 1e-9) << thickness;
  }
}

TEST(Kabsch, ZeroWeightsIgnoreOutliers)
{
  std::mt19937 random(3);
  const Eigen::Isometry3d pose = randomPose(random);
  const PointSet from = randomPoints(random, 7, Eigen::Vector3d(30, 30, 30));
  PointSet to = transformed(pose, from);
  to.row(6) += Eigen::RowVector3d(500, -200, 80);  // a swapped label
  Eigen::VectorXd weights = Eigen::VectorXd::Ones(7);
  weights(6) = 0.0;
  EXPECT_LT((kabsch(from, to, weights).matrix() - pose.matrix()).norm(), 1e-9);
  EXPECT_GT((kabsch(from, to).matrix() - pose.matrix()).norm(), 1e-3);
}

TEST(Kabsch, AMirroredSetStillGivesAProperRotation)
{
  std::mt19937 random(4);
  const PointSet from = randomPoints(random, 10, Eigen::Vector3d(20, 30, 40));
  PointSet to = from;
  to.col(0) = -to.col(0);  // reflection: no rotation maps one onto the other
  const Eigen::Isometry3d fit = kabsch(from, to);
  EXPECT_NEAR(fit.linear().determinant(), 1.0, 1e-12);
  EXPECT_LT((fit.linear().transpose() * fit.linear() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

TEST(Kabsch, FastRotationMatchesTheSvdSolution)
{
  std::mt19937 random(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int trial = 0; trial < 20000; ++trial) {
    Eigen::Matrix3d covariance;
    for (Eigen::Index k = 0; k < 9; ++k)
      covariance(k) = normal(random);
    if (trial % 3 == 1)
      covariance.col(2) *= 1e-4;  // flat clusters
    if (trial % 3 == 2)
      covariance.col(0) = -covariance.col(0);  // reflections
    const Eigen::Matrix3d rotation = kabschRotation(covariance);
    ASSERT_LT((rotation - referenceRotation(covariance)).norm(), 1e-10) << trial;
    ASSERT_NEAR(rotation.determinant(), 1.0, 1e-12);
  }
}

TEST(Kabsch, DegenerateSetsGiveAMinimiser)
{
  PointSet one(1, 3);
  one << 1, 2, 3;
  PointSet moved(1, 3);
  moved << 4, 6, 8;
  const Eigen::Isometry3d single = kabsch(one, moved);
  EXPECT_LT((single * one.row(0).transpose() - moved.row(0).transpose()).norm(), 1e-12);
  PointSet line(3, 3);
  line << 0, 0, 0, 1, 0, 0, 2, 0, 0;
  PointSet shifted = line;
  shifted.col(1).array() += 5.0;
  EXPECT_LT(rigidResidual(kabsch(line, shifted), line, shifted), 1e-12);
}

TEST(Kabsch, BadInputIsRejected)
{
  const PointSet three = PointSet::Ones(3, 3);
  EXPECT_THROW((void)kabsch(three, PointSet::Ones(2, 3)), InvalidArgument);
  EXPECT_THROW((void)kabsch(PointSet(0, 3), PointSet(0, 3)), InvalidArgument);
  PointSet bad = three;
  bad(1, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)kabsch(three, bad), InvalidArgument);
  EXPECT_THROW((void)kabsch(three, three, Eigen::Vector3d(1, -1, 1)), InvalidArgument);
  EXPECT_THROW((void)kabsch(three, three, Eigen::Vector3d::Zero()), InvalidArgument);
  EXPECT_THROW((void)kabsch(three, three, Eigen::Vector2d::Ones()), InvalidArgument);
  EXPECT_THROW((void)rigidResidual(Eigen::Isometry3d::Identity(), three, PointSet::Ones(2, 3)),
               InvalidArgument);
}

} // namespace
} // namespace mocap
