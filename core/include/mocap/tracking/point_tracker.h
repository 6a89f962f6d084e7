#pragma once

#include "mocap/model/point_cloud.h"
#include "mocap/base/job_control.h"

#include <vector>

namespace mocap {

/// How a track predicts its next position from its last ones.
enum class MotionModel
{
  ConstantVelocity,      ///< p̂ₜ = 2pₜ₋₁ − pₜ₋₂
  ConstantAcceleration,  ///< p̂ₜ = 3pₜ₋₁ − 3pₜ₋₂ + pₜ₋₃
};

struct TrackerOptions
{
  /// Gating distance: a point farther than this from a track's prediction never continues it,
  /// in the points' units per frame (`--max-speed`); 0 picks automaticGate().
  double maxSpeed = 0.0;
  MotionModel model = MotionModel::ConstantVelocity;
};

/// One trajectory piece: consecutive frames from `first`, one position each.
struct Fragment
{
  Eigen::Index first = 0;
  std::vector<Eigen::Vector3d> positions;

  [[nodiscard]] Eigen::Index length() const { return static_cast<Eigen::Index>(positions.size()); }
  [[nodiscard]] Eigen::Index last() const { return first + length() - 1; }
  [[nodiscard]] const Eigen::Vector3d& at(Eigen::Index frame) const
  {
    return positions[static_cast<std::size_t>(frame - first)];
  }
};

struct TrackingResult
{
  std::vector<Fragment> fragments;  ///< in order of their first frame
  double gate = 0.0;                ///< the gating distance used
};

/// Half the 10th percentile of the distances between nearest points of a frame, over up to 200
/// frames spread through the cloud: far enough for a marker's deviation from its predicted path,
/// short of the closest neighbouring markers.
/// +infinity when no frame has two points. O(#sampled frames · points²).
[[nodiscard]] double automaticGate(const PointCloud& cloud);

/// Links points into trajectories (paper §2: per frame, prediction then correspondence): every
/// live track predicts its position with `model` (fewer past samples fall back to constant
/// velocity, then to the last position), then points are assigned to tracks by minimising the
/// sum of squared distances to the predictions (assignMinimumCost, gated at maxSpeed²). A track
/// without a point ends; a point without a track starts a new fragment. Fragments never span a
/// frame without their point; joining across gaps is the labeller's job. Throws InvalidArgument
/// for a negative or non-finite maxSpeed or a non-finite point. O(#frames · tracks · points) plus
/// the assignment of the points near more than one track.
/// `job` is checked once a frame.
[[nodiscard]] TrackingResult trackPoints(const PointCloud& cloud, const TrackerOptions& options = {},
                                         const JobControl& job = {});

} // namespace mocap
