#pragma once

#include "mocap/layout/layout_frames.h"
#include "mocap/model/marker_pairs.h"

#include <Eigen/Core>

#include <vector>

namespace mocap {

/// The mirror pairs a layout plan keeps together when no pairs file is given: the resting face is
/// the neutral frame (findNeutralFrame) among the training rows that are not `keyFrames`, and its
/// marker positions go to detectMarkerPairs (labels first, then mirror matching). Shared by the
/// `mocap pfa` command and the studio's layout planning panel so both plan with the same pairs.
/// O(#training · 3·#markers · log #training + detectMarkerPairs).
/// Throws InvalidArgument as findNeutralFrame and detectMarkerPairs (e.g. no training frame).
[[nodiscard]] PairDetection detectLayoutPairs(const LayoutFrames& frames,
                                              const std::vector<Eigen::Index>& keyFrames = {});

} // namespace mocap
