#include "mocap/cleaning/position_change.h"

#include "mocap/base/error.h"

#include <cmath>
#include <string>

namespace mocap {

namespace {

// Whether `patch` is whole and lies inside `take`; the caller's patches may come from another take.
void checkInside(const Take& take, const SamplePatch& patch)
{
  const auto rows = static_cast<Eigen::Index>(patch.frames.size());
  if (patch.positions.rows() != rows || patch.valid.size() != rows)
    throw InvalidArgument("position change: a patch's positions or validity do not match its frames");
  const auto outside = [&](Eigen::Index frame) { return frame < 0 || frame >= take.frameCount(); };
  if (patch.marker < 0 || patch.marker >= take.markerCount())
    throw InvalidArgument("position change: patch of marker " + std::to_string(patch.marker) +
                          " outside the take's " + std::to_string(take.markerCount()) + " markers");
  for (const Eigen::Index frame : patch.frames)
    if (outside(frame))
      throw InvalidArgument("position change: patch frame " + std::to_string(frame) + " outside the take's " +
                            std::to_string(take.frameCount()) + " frames");
}

} // namespace

PositionChange positionChange(const Take& take, const std::vector<SamplePatch>& patches)
{
  PositionChange change;
  double sumSquares = 0.0;
  for (const SamplePatch& patch : patches) {
    checkInside(take, patch);
    for (std::size_t i = 0; i < patch.frames.size(); ++i) {
      const auto row = static_cast<Eigen::Index>(i);
      const Eigen::Index frame = patch.frames[i];
      if (!patch.valid(row) || !take.isValid(frame, patch.marker))
        continue;
      const double d = (patch.positions.row(row).transpose() - take.position(frame, patch.marker)).norm();
      sumSquares += d * d;
      // The first sample counted names the place even when nothing moves.
      if (d > change.max || change.samples == 0) {
        change.max = d;
        change.maxMarker = patch.marker;
        change.maxFrame = frame;
      }
      ++change.samples;
    }
  }
  if (change.samples > 0)
    change.rms = std::sqrt(sumSquares / static_cast<double>(change.samples));
  return change;
}

} // namespace mocap
