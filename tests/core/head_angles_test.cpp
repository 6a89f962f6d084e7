#include "mocap/cleaning/head_angles.h"

#include "mocap/base/error.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace mocap {
namespace {

Eigen::Matrix3d yawPitchRoll(double yaw, double pitch, double roll)
{
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

TEST(HeadAngles, YawPitchAndRollComeBackInTheFacesAxes)
{
  // A Z-up take whose face looks along −Y: the face's Y (up) is the take's Z, its Z (out of the
  // face) the take's −Y.
  Eigen::Matrix3d takeToFace;
  takeToFace << 1, 0, 0,  //
      0, 0, 1,            //
      0, -1, 0;
  const double angles[][3] = {{0.0, 0.0, 0.0}, {0.3, 0.0, 0.0}, {0.0, -0.2, 0.0}, {0.1, 0.2, -0.4}, {-1.2, 0.5, 0.7}};
  HeadMotion motion;
  for (const auto& a : angles) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = takeToFace.transpose() * yawPitchRoll(a[0], a[1], a[2]) * takeToFace;
    pose.translation() << 5.0, -3.0, 100.0;  // where the head is does not turn it
    motion.poses.push_back(pose);
  }
  const Eigen::MatrixXd got = headYawPitchRoll(motion, takeToFace);
  ASSERT_EQ(got.rows(), 5);
  for (Eigen::Index f = 0; f < got.rows(); ++f)
    for (Eigen::Index c = 0; c < 3; ++c)
      EXPECT_NEAR(got(f, c), angles[f][c], 1e-12) << f << ' ' << c;
  // Turning about the take's up axis (Z here) is yaw.
  motion.poses.assign(1, Eigen::Isometry3d(Eigen::AngleAxisd(0.25, Eigen::Vector3d::UnitZ())));
  EXPECT_NEAR(headYawPitchRoll(motion, takeToFace)(0, 0), 0.25, 1e-12);
  EXPECT_THROW((void)headYawPitchRoll(motion, 2.0 * takeToFace), InvalidArgument);
}

} // namespace
} // namespace mocap
