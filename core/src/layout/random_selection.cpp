// The random baseline (selectRandom, marker_selection.h).

#include "mocap/layout/marker_selection.h"

#include "mocap/base/error.h"
#include "mocap/base/random.h"

#include "selection_units.h"

#include <string>

namespace mocap {

using layout_internal::markersOfUnits;
using layout_internal::sizeReachable;

std::optional<std::vector<Eigen::Index>> selectRandom(const MarkerSymmetry& symmetry, Eigen::Index size,
                                                      std::uint64_t seed)
{
  if (size < 1 || size > symmetry.markerCount())
    throw InvalidArgument("random selection: the size must be between 1 and " +
                          std::to_string(symmetry.markerCount()) + ", not " + std::to_string(size));
  if (!sizeReachable(symmetry, size))
    return std::nullopt;
  const auto& units = symmetry.units();
  std::vector<std::size_t> order(units.size());
  Random random(seed);
  for (int attempt = 0; attempt < 1000; ++attempt) {
    for (std::size_t u = 0; u < order.size(); ++u)
      order[u] = u;
    random.shuffle(order.begin(), order.end());
    std::vector<bool> selected(units.size(), false);
    Eigen::Index count = 0;
    for (const std::size_t u : order) {
      const auto width = static_cast<Eigen::Index>(units[u].size());
      if (count + width <= size) {
        selected[u] = true;
        count += width;
      }
    }
    if (count == size)
      return markersOfUnits(symmetry, selected);
  }
  return std::nullopt;
}

} // namespace mocap
