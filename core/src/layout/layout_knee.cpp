// The knee of an error curve (chooseKnee, marker_selection.h): Kneedle.

#include "mocap/layout/marker_selection.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mocap {

std::size_t chooseKnee(const std::vector<Eigen::Index>& sizes, const std::vector<double>& errorA,
                       const std::vector<double>& errorB)
{
  if (sizes.empty())
    throw InvalidArgument("knee: there are no points");
  if (errorA.size() != sizes.size() || errorB.size() != sizes.size())
    throw InvalidArgument("knee: the sizes and errors differ in length");
  for (std::size_t i = 0; i < sizes.size(); ++i)
    if (!std::isfinite(errorA[i]) || !std::isfinite(errorB[i]))
      throw InvalidArgument("knee: an error is not finite");
  if (sizes.size() < 3)
    return 0;
  const double maxA = *std::max_element(errorA.begin(), errorA.end());
  const double maxB = *std::max_element(errorB.begin(), errorB.end());
  std::vector<double> y(sizes.size());
  for (std::size_t i = 0; i < sizes.size(); ++i)
    y[i] = 0.5 * ((maxA > 0.0 ? errorA[i] / maxA : 0.0) + (maxB > 0.0 ? errorB[i] / maxB : 0.0));
  const auto first = static_cast<double>(sizes.front());
  const double span = std::max(1.0, static_cast<double>(sizes.back()) - first);
  std::size_t knee = 0;
  double deepest = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const double x = (static_cast<double>(sizes[i]) - first) / span;
    const double chord = y.front() + (y.back() - y.front()) * x;
    if (chord - y[i] > deepest) {
      deepest = chord - y[i];
      knee = i;
    }
  }
  return knee;
}

} // namespace mocap
