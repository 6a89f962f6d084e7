#include "mocap/layout/layout_symmetry.h"

#include "mocap/layout/blendshape_basis.h"

#include <algorithm>

namespace mocap {

PairDetection detectLayoutPairs(const LayoutFrames& frames, const std::vector<Eigen::Index>& keyFrames)
{
  // Key poses are extremes by choice; the resting face is looked for among the other frames.
  std::vector<Eigen::Index> candidates;
  for (const Eigen::Index row : frames.training)
    if (std::find(keyFrames.begin(), keyFrames.end(), row) == keyFrames.end())
      candidates.push_back(row);
  const Eigen::Index neutral = findNeutralFrame(frames.frames, candidates);
  Eigen::MatrixX3d positions(frames.markerCount(), 3);
  for (Eigen::Index m = 0; m < frames.markerCount(); ++m)
    positions.row(m) = frames.frames.row(neutral).segment<3>(3 * m);
  return detectMarkerPairs(positions, frames.labels);
}

} // namespace mocap
