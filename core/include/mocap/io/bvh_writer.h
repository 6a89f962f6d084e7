#pragma once

#include "mocap/model/take.h"

#include <Eigen/Geometry>

#include <filesystem>
#include <string>
#include <vector>

namespace mocap {

struct BvhOptions
{
  /// Per frame, the head pose mapping head space to take space; empty means identity throughout.
  std::vector<Eigen::Isometry3d> headPoses;
};

/// Euler angles of `rotation` in degrees as (z, x, y), the BVH channel order, such that
/// rotation = Rz(z) · Rx(x) · Ry(y). x is in [−90, 90], z and y in [−180, 180]; in gimbal lock
/// (x = ±90) y is 0 and z carries the whole turn about the vertical. O(1).
[[nodiscard]] Eigen::Vector3d zxyEulerDegrees(const Eigen::Matrix3d& rotation);

/// Rz(z) · Rx(x) · Ry(y) from (z, x, y) in degrees; the inverse of zxyEulerDegrees. O(1).
[[nodiscard]] Eigen::Matrix3d zxyRotation(const Eigen::Vector3d& zxyDegrees);

/// The take as a BVH animation for animation tools: a `Head` root with 6 channels (head
/// translation, then Zrotation Xrotation Yrotation in degrees) and one child joint per marker
/// (whitespace, braces and control characters in labels become '_', names made unique) with 3
/// position channels and an End Site. A marker's OFFSET is its first valid sample in head space;
/// its channels hold its head-space position every frame, which importers such as Blender's use in
/// place of the OFFSET. BVH has no gaps: a missing sample repeats the head-space position of the
/// marker's nearest valid sample in time (the earlier one on a tie), and a marker never valid
/// stays at 0 0 0. Units are the take's. Throws InvalidArgument when `options.headPoses` is not
/// empty and its size differs from frameCount(). O(#frames · #markers).
[[nodiscard]] std::string formatBvh(const Take& take, const BvhOptions& options = {});

/// Writes formatBvh(take, options) atomically. Throws IoError, InvalidArgument.
/// O(#frames · #markers).
void writeBvh(const Take& take, const std::filesystem::path& path, const BvhOptions& options = {});

} // namespace mocap
