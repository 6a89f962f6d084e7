#include "mocap/cleaning/flags_beside_repairs.h"

#include <algorithm>
#include <utility>

namespace mocap {

namespace {

using Sample = std::pair<Eigen::Index, Eigen::Index>;  // (marker, frame)

// The samples of `repairs` the take still holds as repaired, sorted.
std::vector<Sample> stillRepaired(const Take& take, const std::vector<SamplePatch>& repairs)
{
  std::vector<Sample> repaired;
  for (const SamplePatch& patch : repairs) {
    if (patch.marker < 0 || patch.marker >= take.markerCount())
      continue;
    for (std::size_t i = 0; i < patch.size() && static_cast<Eigen::Index>(i) < patch.positions.rows(); ++i) {
      const Eigen::Index frame = patch.frames[i];
      if (frame >= 0 && frame < take.frameCount() && take.isValid(frame, patch.marker) &&
          take.position(frame, patch.marker) == patch.positions.row(static_cast<Eigen::Index>(i)).transpose())
        repaired.emplace_back(patch.marker, frame);
    }
  }
  std::sort(repaired.begin(), repaired.end());
  return repaired;
}

} // namespace

std::size_t flagsBesideRepairs(const Take& take, const std::vector<SpikeFlag>& flags,
                               const std::vector<SamplePatch>& repairs)
{
  const std::vector<Sample> repaired = stillRepaired(take, repairs);
  std::size_t beside = 0;
  for (const SpikeFlag& flag : flags) {
    const auto near =
        std::lower_bound(repaired.begin(), repaired.end(), Sample{flag.marker, flag.frame - kFramesBesideRepair});
    if (near != repaired.end() && near->first == flag.marker && near->second <= flag.frame + kFramesBesideRepair)
      ++beside;
  }
  return beside;
}

} // namespace mocap
