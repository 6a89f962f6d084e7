#include "mocap/cleaning/fill/gap_prediction.h"

#include "mocap/base/error.h"

namespace mocap {

namespace {

const bool* checkedValidity(const Take& take, Eigen::Index marker, Eigen::Index first, Eigen::Index length,
                            const ValidMask* markerValid)
{
  if (marker < 0 || marker >= take.markerCount())
    throw InvalidArgument("gap marker " + std::to_string(marker) + " out of range");
  if (length < 1 || first < 0 || first > take.frameCount() - length)
    throw InvalidArgument("gap of " + std::to_string(length) + " frames at frame " + std::to_string(first) +
                          " does not lie inside the take");
  if (markerValid != nullptr && markerValid->size() != take.frameCount())
    throw InvalidArgument("gap validity mask has the wrong size");
  const bool* valid = markerValid != nullptr ? markerValid->data() : take.valid().col(marker).data();
  for (Eigen::Index f = first; f < first + length; ++f)
    if (valid[f])
      throw InvalidArgument("frame " + std::to_string(f) + " of marker " + take.label(marker) +
                            " is valid, so it is not part of a gap");
  return valid;
}

} // namespace

GapQuery::GapQuery(const Take& take_, Eigen::Index marker_, Eigen::Index first_, Eigen::Index length_,
                   const ValidMask* markerValid_)
    : take(take_), marker(marker_), first(first_), length(length_),
      markerValid(checkedValidity(take_, marker_, first_, length_, markerValid_), take_.frameCount())
{}

} // namespace mocap
