#pragma once

#include "mocap/model/take.h"

#include <vector>

namespace mocap {

/// A maximal run of consecutive valid samples of one trajectory: frames [first, first + length).
struct ValidRun
{
  Eigen::Index first = 0;
  Eigen::Index length = 0;
};

/// Every run of valid samples in `valid`, in frame order: the complement of findGaps, and the unit
/// every filter works on so that a gap never reaches it. O(#frames). No paper equation: the paper
/// (§4.2) fits whole tracked trajectories; we fit each valid run so a gap never enters a fit.
[[nodiscard]] std::vector<ValidRun> findValidRuns(const Eigen::Ref<const ValidMask>& valid);

} // namespace mocap
