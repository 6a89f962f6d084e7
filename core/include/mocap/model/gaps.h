#pragma once

#include "mocap/model/take.h"

#include <vector>

namespace mocap {

/// A run of invalid samples of one marker.
struct Gap
{
  Eigen::Index marker = 0;
  Eigen::Index firstFrame = 0;  ///< 0-based frame index of the first missing sample
  Eigen::Index length = 0;
  /// True when the gap touches the first or last frame (nothing to interpolate from on one side).
  bool atEdge = false;
};

/// Every run of invalid samples in `valid` (one trajectory), in frame order. O(#frames).
[[nodiscard]] std::vector<Gap> findGaps(const Eigen::Ref<const ValidMask>& valid, Eigen::Index marker = 0);

/// Every gap of every marker point (markerPoints: model outputs have none), markers in order.
/// Markers never valid are one gap spanning the take. O(#frames · #markers).
[[nodiscard]] std::vector<Gap> findGaps(const Take& take);

/// Every gap of the points `points` (indices into the take, e.g. model outputs a view shows too),
/// in their order. O(#frames · #points).
[[nodiscard]] std::vector<Gap> findGaps(const Take& take, const std::vector<Eigen::Index>& points);

} // namespace mocap
