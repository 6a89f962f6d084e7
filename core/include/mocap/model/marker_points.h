#pragma once

#include "mocap/model/take.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace mocap {

/// Which points of a take are marker positions. C3D files from Vicon Nexus store model outputs
/// (joint angles, forces, moments, powers, and virtual points such as segment axes) as points
/// beside the markers; they are kept in the take
/// and written back, but views, gap lists, cleaning, layout planning and statistics leave them
/// out. This is the one rule they all use.

/// True when point `point` is a measured marker (Take::pointType is Marker). O(1).
[[nodiscard]] bool isMarker(const Take& take, Eigen::Index point);

/// The marker points of `take`, ascending. O(#points).
[[nodiscard]] std::vector<Eigen::Index> markerPoints(const Take& take);

/// The labels of markerPoints(take), in take order. O(#points).
[[nodiscard]] std::vector<std::string> markerLabels(const Take& take);

/// The points that are not markers (model outputs), ascending. O(#points).
[[nodiscard]] std::vector<Eigen::Index> modelOutputPoints(const Take& take);

/// Fraction of valid samples over the marker points and frames: the valid fraction reports, quality
/// gates and statistics give (Take::validFraction counts every point). 0 for a take without marker
/// points or frames. O(#frames · #markers).
[[nodiscard]] double markerValidFraction(const Take& take);

/// How many points of each PointType the take holds, indexed by the enum's value. O(#points).
[[nodiscard]] std::array<Eigen::Index, kPointTypeCount> pointTypeCounts(const Take& take);

/// "70 model outputs (12 angles, 8 forces, 8 moments, 6 powers, 36 virtual points)", the kinds the
/// take holds in enum order; "" when every point is a marker. O(#points).
[[nodiscard]] std::string describeModelOutputs(const Take& take);

/// The take with its marker points only, for a file that holds marker positions and cannot say a
/// column is an angle (TRC, BVH: their readers would take model outputs for markers); nullopt when
/// the take has no model outputs (write it as it is). Throws InvalidArgument naming `file` ("a TRC
/// file") when the take has only model outputs. O(take size) when it copies, else O(#points).
[[nodiscard]] std::optional<Take> withoutModelOutputs(const Take& take, const std::string& file);

} // namespace mocap
