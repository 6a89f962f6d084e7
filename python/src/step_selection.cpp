#include "step_selection.h"

#include "mocap/base/error.h"

#include <algorithm>

namespace mocap::python {

std::optional<StepSelection> StepSelection::of(const Take& take, const std::optional<std::vector<std::string>>& markers,
                                               const std::optional<std::pair<long long, long long>>& frames)
{
  if (!markers && !frames)
    return std::nullopt;
  StepSelection selection;
  if (markers) {
    selection.labels = *markers;
    selection.markers = markerIndices(take, *markers);
    std::sort(selection.markers.begin(), selection.markers.end());
  }
  if (frames) {
    const long long first = frames->first - take.firstFrame();
    const long long last = frames->second - take.firstFrame();
    if (first > last || first < 0 || last >= take.frameCount())
      throw InvalidArgument("frames (" + std::to_string(frames->first) + ", " + std::to_string(frames->second) +
                            ") must be a range (first, last) within the take's frames " +
                            std::to_string(take.firstFrame()) + "…" +
                            std::to_string(take.firstFrame() + take.frameCount() - 1));
    selection.ranged = true;
    selection.first = static_cast<Eigen::Index>(first);
    selection.last = static_cast<Eigen::Index>(last);
  }
  return selection;
}

bool StepSelection::holdsMarker(Eigen::Index marker) const
{
  return markers.empty() || std::binary_search(markers.begin(), markers.end(), marker);
}

bool StepSelection::holds(Eigen::Index marker, Eigen::Index frame) const
{
  return holdsMarker(marker) && (!ranged || (frame >= first && frame <= last));
}

bool StepSelection::overlaps(const Gap& gap) const
{
  return holdsMarker(gap.marker) && (!ranged || (gap.firstFrame <= last && gap.firstFrame + gap.length - 1 >= first));
}

std::vector<SamplePatch> StepSelection::within(std::vector<SamplePatch> patches) const
{
  std::vector<SamplePatch> kept;
  for (SamplePatch& patch : patches) {
    if (!holdsMarker(patch.marker))
      continue;
    if (ranged)
      patch = patchWithin(patch, first, last);
    if (!patch.empty())
      kept.push_back(std::move(patch));
  }
  return kept;
}

void StepSelection::narrow(ProcessingStep& step, const Take& take) const
{
  step.markers = labels;
  if (ranged) {
    step.firstFrame = take.firstFrame() + first;
    step.lastFrame = take.firstFrame() + last;
  }
}

Eigen::Index sampleCount(const std::vector<SamplePatch>& patches)
{
  Eigen::Index samples = 0;
  for (const SamplePatch& patch : patches)
    samples += static_cast<Eigen::Index>(patch.size());
  return samples;
}

} // namespace mocap::python
