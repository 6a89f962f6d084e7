#pragma once

#include "mocap/cleaning/head_stabilization.h"

#include <Eigen/Core>

namespace mocap {

/// The head's rotation per frame as yaw, pitch and roll in radians (#frames × 3), relative to the
/// head in the motion's reference frame, in a face's axes: `takeToFace` turns the take's axes into
/// the face's (Y up, Z out of the face, X to the face's left: a face mesh's axes, as the solver's
/// retarget rotation gives them). The rotation R = Ry(yaw) · Rx(pitch) · Rz(roll): yaw turns about
/// the up axis, pitch about the ear-to-ear axis (positive tips the chin down), roll about the axis
/// out of the face; the columns Live Link Face's HeadYaw, HeadPitch and HeadRoll hold. Not a paper
/// equation. Throws InvalidArgument unless takeToFace is a rotation. O(#frames).
[[nodiscard]] Eigen::MatrixXd headYawPitchRoll(const HeadMotion& motion, const Eigen::Matrix3d& takeToFace);

} // namespace mocap
