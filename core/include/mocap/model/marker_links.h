#pragma once

#include "mocap/model/take.h"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace mocap {

/// A line drawn between two markers (indices, first < second) so the face reads as a surface.
using MarkerLink = std::pair<Eigen::Index, Eigen::Index>;

/// Links each point (a row) to its `neighbours` nearest other points, dropping links longer than
/// `maxRatio` × the median link (infinity keeps all), as row index pairs, sorted, without repeats.
/// Throws InvalidArgument for neighbours < 1 or maxRatio not > 0. O(#points² log #points).
[[nodiscard]] std::vector<MarkerLink> nearestNeighbourLinks(const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>& points,
                                                            int neighbours, double maxRatio);

/// The same over the marker points (no model outputs) valid (and finite) in `frame` of a take, as marker indices: by
/// default each to its three nearest, without links over twice the median (a stray marker is
/// not drawn across the face). Also throws InvalidArgument for a frame outside the take.
[[nodiscard]] std::vector<MarkerLink> nearestNeighbourLinks(const Take& take, Eigen::Index frame, int neighbours = 3,
                                                            double maxRatio = 2.0);

} // namespace mocap
