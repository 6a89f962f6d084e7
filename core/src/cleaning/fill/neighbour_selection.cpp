#include "mocap/cleaning/fill/neighbour_selection.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace mocap {

std::vector<Eigen::Index> markersValidThrough(const Take& take, Eigen::Index marker, Eigen::Index from,
                                              Eigen::Index to)
{
  std::vector<Eigen::Index> markers;
  if (from < 0 || to >= take.frameCount() || to < from)
    return markers;
  const auto valid = take.valid();
  const auto length = static_cast<std::size_t>(to - from + 1);
  for (Eigen::Index j = 0; j < take.markerCount(); ++j) {
    // A bool is one byte, 0 when false: memchr scans the run with vector instructions.
    const void* run = valid.col(j).data() + from;
    if (j != marker && std::memchr(run, 0, length) == nullptr)
      markers.push_back(j);
  }
  return markers;
}

std::vector<Eigen::Index> nearestMarkers(const Take& take, Eigen::Index marker,
                                         const std::vector<Eigen::Index>& candidates,
                                         const std::vector<Eigen::Index>& frames, std::size_t count)
{
  std::vector<std::pair<double, Eigen::Index>> ranked;
  ranked.reserve(candidates.size());
  const auto own = take.trajectory(marker);
  for (const Eigen::Index j : candidates) {
    const auto other = take.trajectory(j);
    double distance = 0.0;
    for (const Eigen::Index f : frames)
      distance += (other.row(f) - own.row(f)).norm();
    ranked.emplace_back(distance, j);
  }
  count = std::min(count, ranked.size());
  std::partial_sort(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(count), ranked.end());
  std::vector<Eigen::Index> nearest;
  nearest.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
    nearest.push_back(ranked[i].second);
  return nearest;
}

} // namespace mocap
