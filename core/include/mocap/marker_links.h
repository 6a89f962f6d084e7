#pragma once

#include "mocap/take.h"

#include <utility>
#include <vector>

namespace mocap {

/// A line drawn between two markers (indices, first < second) so the face reads as a surface.
using MarkerLink = std::pair<Eigen::Index, Eigen::Index>;

/// The frame with the most valid markers (the first of equals): a stand-in for the neutral frame
/// when none is given. −1 for an empty take. O(#frames · #markers).
[[nodiscard]] Eigen::Index mostCompleteFrame(const Take& take);

/// Links each marker valid in `frame` to its `neighbours` nearest valid markers there, dropping
/// links longer than `maxRatio` × the median link (a stray marker does not get drawn across the
/// face). Sorted, without repeats. Throws InvalidArgument for a frame outside the take,
/// neighbours < 1 or maxRatio ≤ 0. O(#markers² log #markers).
[[nodiscard]] std::vector<MarkerLink> nearestNeighbourLinks(const Take& take, Eigen::Index frame, int neighbours = 3,
                                                            double maxRatio = 2.0);

} // namespace mocap
