#pragma once

#include "mocap/model/take.h"

#include <vector>

namespace mocap {

/// Markers other than `marker` that are valid in every frame from `from` to `to` (inclusive), in
/// index order: the neighbours a gap filler can rely on throughout a gap. Empty when the range is
/// not inside the take. Not a paper equation. O(#markers · (to − from)).
[[nodiscard]] std::vector<Eigen::Index> markersValidThrough(const Take& take, Eigen::Index marker,
                                                            Eigen::Index from, Eigen::Index to);

/// The `count` markers of `candidates` nearest to `marker`, the distance averaged over the
/// `frames` given (each valid for all of them), nearest first (ties by index); fewer when there
/// are fewer candidates. Not a paper equation (eqs 3-7 choose per frame; this chooses once per
/// gap). O(#candidates · #frames + #candidates · log #candidates).
[[nodiscard]] std::vector<Eigen::Index> nearestMarkers(const Take& take, Eigen::Index marker,
                                                       const std::vector<Eigen::Index>& candidates,
                                                       const std::vector<Eigen::Index>& frames,
                                                       std::size_t count);

} // namespace mocap
