#pragma once

#include "mocap/cleaning/spike_detection.h"
#include "mocap/model/sample_patch.h"
#include "mocap/model/take.h"

#include <cstddef>
#include <vector>

namespace mocap {

/// Frames either side of a repaired sample within which a new spike flag counts as beside it.
inline constexpr Eigen::Index kFramesBesideRepair = 2;

/// How many of `flags` lie within kFramesBesideRepair frames of a sample `repairs` replaced and
/// the take still holds as repaired: valid, at the repair's very position. An undone or since
/// edited repair does not count, nor a repair of a marker or frame the take no longer has (the
/// repairs may be older than the take). Why a repair seems to breed flags: a glitch longer than
/// a few frames is found a part at a time, its worst samples first, and its rest stands out
/// beside the repaired samples. O(#repaired · log #repaired + #flags · log #repaired).
[[nodiscard]] std::size_t flagsBesideRepairs(const Take& take, const std::vector<SpikeFlag>& flags,
                                             const std::vector<SamplePatch>& repairs);

} // namespace mocap
