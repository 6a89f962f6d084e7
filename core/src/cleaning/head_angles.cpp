#include "mocap/cleaning/head_angles.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <cmath>

namespace mocap {

Eigen::MatrixXd headYawPitchRoll(const HeadMotion& motion, const Eigen::Matrix3d& takeToFace)
{
  if (!takeToFace.allFinite() || !(takeToFace.transpose() * takeToFace).isIdentity(1e-6) ||
      takeToFace.determinant() < 0.0)
    throw InvalidArgument("head angles: the take-to-face axes are not a rotation");
  const auto frames = static_cast<Eigen::Index>(motion.poses.size());
  Eigen::MatrixXd angles(frames, 3);
  for (Eigen::Index f = 0; f < frames; ++f) {
    // The head's turn from the reference frame, seen in the face's axes.
    const Eigen::Matrix3d r = takeToFace * motion.poses[static_cast<std::size_t>(f)].rotation() * takeToFace.transpose();
    // R = Ry(yaw)·Rx(pitch)·Rz(roll): row 1 is (cos p sin r, cos p cos r, −sin p), column 2 is
    // (sin y cos p, −sin p, cos y cos p).
    angles(f, 0) = std::atan2(r(0, 2), r(2, 2));
    angles(f, 1) = std::asin(std::clamp(-r(1, 2), -1.0, 1.0));
    angles(f, 2) = std::atan2(r(1, 0), r(1, 1));
  }
  return angles;
}

} // namespace mocap
