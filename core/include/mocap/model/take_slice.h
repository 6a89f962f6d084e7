#pragma once

#include "mocap/model/take.h"

namespace mocap {

/// Frames [begin, end) of `take` as a take of their own: labels, point types, rate, units, positions, validity,
/// residuals, camera masks and sample states, with the first frame number moved to frame `begin`
/// (e.g. to export part of a take). Analog data, events and the C3D parameter tree are not copied
/// (they would describe the whole take). Throws InvalidArgument unless 0 ≤ begin < end ≤
/// frameCount(). O((end − begin) · #markers).
[[nodiscard]] Take sliceFrames(const Take& take, Eigen::Index begin, Eigen::Index end);

} // namespace mocap
