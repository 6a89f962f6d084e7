// Replacing flagged samples from their unflagged neighbours (replaceSpikes, eq 10).

#include "mocap/cleaning/spike_detection.h"

#include "mocap/base/error.h"

#include "spike_detector_parts.h"

#include <algorithm>
#include <string>

namespace mocap {

namespace spikes {

namespace {

// Least-squares line through (t, p) evaluated at `at`; a single point is held constant.
Eigen::RowVector3d extrapolate(const std::vector<Eigen::Index>& frames, const Trajectory& xyz,
                               Eigen::Index at)
{
  const auto count = static_cast<double>(frames.size());
  double meanT = 0.0;
  Eigen::RowVector3d meanP = Eigen::RowVector3d::Zero();
  for (Eigen::Index f : frames) {
    meanT += static_cast<double>(f);
    meanP += xyz.row(f);
  }
  meanT /= count;
  meanP /= count;
  double stt = 0.0;
  Eigen::RowVector3d stp = Eigen::RowVector3d::Zero();
  for (Eigen::Index f : frames) {
    const double dt = static_cast<double>(f) - meanT;
    stt += dt * dt;
    stp += dt * (xyz.row(f) - meanP);
  }
  if (stt <= 0.0)
    return meanP;
  return meanP + (static_cast<double>(at) - meanT) * (stp / stt);
}

} // namespace

// The replacements of replaceSpikes for one trajectory: `flagged` holds valid frames, ascending
// and unique; appends the replaced frames and their positions. O(#flags · log #flags).
void replaceFlagged(const Trajectory& xyz, const Eigen::Ref<const ValidMask>& valid,
                    const std::vector<Eigen::Index>& flagged, std::vector<Eigen::Index>& frames,
                    std::vector<Eigen::RowVector3d>& positions)
{
  const Eigen::Index frameCount = xyz.rows();
  auto isFlagged = [&](Eigen::Index f) { return std::binary_search(flagged.begin(), flagged.end(), f); };
  auto usable = [&](Eigen::Index f) { return f >= 0 && f < frameCount && valid(f) && !isFlagged(f); };
  std::size_t i = 0;
  while (i < flagged.size()) {
    // A block of consecutive flagged frames [first, last].
    const Eigen::Index first = flagged[i];
    Eigen::Index last = first;
    while (i + 1 < flagged.size() && flagged[i + 1] == last + 1)
      last = flagged[++i];
    ++i;
    const bool left = usable(first - 1);
    const bool right = usable(last + 1);
    std::vector<Eigen::Index> support;
    if (!left && right) {
      for (Eigen::Index f = last + 1; f < frameCount && valid(f) && support.size() < 4; ++f)
        if (!isFlagged(f))
          support.push_back(f);
    } else if (left && !right) {
      for (Eigen::Index f = first - 1; f >= 0 && valid(f) && support.size() < 4; --f)
        if (!isFlagged(f))
          support.push_back(f);
    }
    if (!left && !right)
      continue;  // the block is a whole run: nothing to rebuild it from
    for (Eigen::Index f = first; f <= last; ++f) {
      frames.push_back(f);
      if (left && right) {
        const double u = static_cast<double>(f - first + 1) / static_cast<double>(last - first + 2);
        positions.push_back((1.0 - u) * xyz.row(first - 1) + u * xyz.row(last + 1));  // eq 10 for one sample
      } else {
        positions.push_back(extrapolate(support, xyz, f));
      }
    }
  }
}

} // namespace spikes

std::vector<SamplePatch> replaceSpikes(const Take& take, const std::vector<SpikeFlag>& flags)
{
  for (const SpikeFlag& flag : flags)
    if (flag.marker < 0 || flag.marker >= take.markerCount() || flag.frame < 0 ||
        flag.frame >= take.frameCount())
      throw InvalidArgument("spike flag (marker " + std::to_string(flag.marker) + ", frame " +
                            std::to_string(flag.frame) + ") lies outside the take");
  std::vector<SpikeFlag> sorted;
  sorted.reserve(flags.size());
  for (const SpikeFlag& flag : flags)
    if (take.isValid(flag.frame, flag.marker))
      sorted.push_back(flag);
  std::sort(sorted.begin(), sorted.end(), [](const SpikeFlag& a, const SpikeFlag& b) {
    return a.marker != b.marker ? a.marker < b.marker : a.frame < b.frame;
  });
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());

  std::vector<SamplePatch> patches;
  std::size_t b = 0;
  std::vector<Eigen::Index> flagged;
  while (b < sorted.size()) {
    const Eigen::Index marker = sorted[b].marker;
    flagged.clear();
    for (; b < sorted.size() && sorted[b].marker == marker; ++b)
      flagged.push_back(sorted[b].frame);
    std::vector<Eigen::Index> frames;
    std::vector<Eigen::RowVector3d> positions;
    spikes::replaceFlagged(take.trajectory(marker), take.valid().col(marker), flagged, frames, positions);
    if (!frames.empty()) {
      Eigen::Matrix<double, Eigen::Dynamic, 3> matrix(static_cast<Eigen::Index>(positions.size()), 3);
      for (std::size_t r = 0; r < positions.size(); ++r)
        matrix.row(static_cast<Eigen::Index>(r)) = positions[r];
      patches.push_back(makePatch(marker, std::move(frames), std::move(matrix), SampleOrigin::Edited));
    }
  }
  return patches;
}

} // namespace mocap
