#include "selection_units.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <string>

namespace mocap::layout_internal {

void checkSymmetry(const MarkerSymmetry& symmetry, Eigen::Index markers)
{
  if (symmetry.markerCount() != markers)
    throw InvalidArgument("marker selection: the symmetry covers " + std::to_string(symmetry.markerCount()) +
                          " markers, the frames " + std::to_string(markers));
}

void checkTraining(const Eigen::Ref<const Eigen::MatrixXd>& training)
{
  if (training.cols() < 6 || training.cols() % 3 != 0)
    throw InvalidArgument("marker selection needs at least two markers (3 coordinates each), got " +
                          std::to_string(training.cols()) + " coordinates");
  if (!training.allFinite())
    throw InvalidArgument("marker selection: a training value is not finite");
}

std::vector<Eigen::Index> markersOfUnits(const MarkerSymmetry& symmetry, const std::vector<bool>& selected)
{
  std::vector<Eigen::Index> markers;
  for (std::size_t u = 0; u < selected.size(); ++u)
    if (selected[u])
      for (const Eigen::Index m : symmetry.units()[u])
        markers.push_back(m);
  std::sort(markers.begin(), markers.end());
  return markers;
}

bool sizeReachable(const MarkerSymmetry& symmetry, Eigen::Index size)
{
  Eigen::Index pairs = 0, singles = 0;
  for (const auto& unit : symmetry.units())
    (unit.size() == 2 ? pairs : singles) += 1;
  for (Eigen::Index a = 0; a <= pairs; ++a)
    if (size - 2 * a >= 0 && size - 2 * a <= singles)
      return true;
  return false;
}

} // namespace mocap::layout_internal
