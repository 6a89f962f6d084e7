#pragma once

#include "mocap/model/take.h"

#include <vector>

namespace mocap {

/// True when the sample can be written as a position: valid and finite. O(1).
[[nodiscard]] bool usableSample(const Take& take, Eigen::Index frame, Eigen::Index marker);

/// For each frame, the nearest frame in which `marker` is usable (the earlier one on a tie), or −1
/// for every frame when it never is: how writers of formats without gaps (BVH, FBX) hold a marker
/// through its gaps. O(#frames).
[[nodiscard]] std::vector<Eigen::Index> nearestUsableFrames(const Take& take, Eigen::Index marker);

} // namespace mocap
