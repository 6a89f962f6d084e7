#pragma once

#include "mocap/model/sample_patch.h"
#include "mocap/model/take.h"

#include <vector>

namespace mocap {

/// How far a set of patches moves the samples it replaces: what a technician judges a smoothing
/// by. Distances are in the take's units.
struct PositionChange
{
  double rms = 0.0;              ///< root mean square of the distances; 0 when no sample counts
  double max = 0.0;              ///< the largest distance
  Eigen::Index maxMarker = -1;   ///< where the largest distance is; -1 when no sample counts
  Eigen::Index maxFrame = 0;     ///< 0-based frame of the largest distance
  Eigen::Index samples = 0;      ///< samples counted: valid both in the take and in the patch
};

/// The Euclidean distances between the positions of `patches` and those of `take` they would
/// replace, over every sample valid both before and after (a gap filled or a sample deleted
/// moves nothing). On ties the first largest distance is kept, so whenever a sample counts,
/// maxMarker names one (the first, when nothing moves). No patch or no such sample gives an empty
/// change (samples 0, maxMarker -1). Throws InvalidArgument for a patch whose marker or a frame lies
/// outside the take, or whose positions or validity do not match its frames. O(total patch size).
[[nodiscard]] PositionChange positionChange(const Take& take, const std::vector<SamplePatch>& patches);

} // namespace mocap
