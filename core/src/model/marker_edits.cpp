#include "mocap/model/marker_edits.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <numeric>

namespace mocap {

namespace {

void checkMarker(const Take& take, Eigen::Index marker)
{
  if (marker < 0 || marker >= take.markerCount())
    throw InvalidArgument("marker index " + std::to_string(marker) + " is outside the take (" +
                          std::to_string(take.markerCount()) + " markers)");
}

// Marker `from`'s samples over [first, last] as a patch for marker `to`.
SamplePatch copyRange(const Take& take, Eigen::Index from, Eigen::Index to, Eigen::Index first, Eigen::Index last)
{
  SamplePatch patch;
  patch.marker = to;
  const Eigen::Index count = last - first + 1;
  patch.frames.resize(static_cast<std::size_t>(count));
  std::iota(patch.frames.begin(), patch.frames.end(), first);
  patch.positions = take.trajectory(from).middleRows(first, count);
  patch.valid = take.valid().col(from).segment(first, count);
  patch.residuals = take.residuals().col(from).segment(first, count);
  patch.states.reserve(static_cast<std::size_t>(count));
  patch.cameraMasks.reserve(static_cast<std::size_t>(count));
  for (Eigen::Index f = first; f <= last; ++f) {
    patch.states.push_back(take.state(f, from));
    patch.cameraMasks.push_back(take.cameraMasks()(f, from));
  }
  return patch;
}

} // namespace

MarkerColumn averagedMarker(const Take& take, const std::vector<Eigen::Index>& sources, std::string label)
{
  if (sources.empty())
    throw InvalidArgument("an averaged marker needs at least one source marker");
  for (Eigen::Index s : sources)
    checkMarker(take, s);
  std::vector<Eigen::Index> sorted = sources;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    throw InvalidArgument("an averaged marker's sources must be different markers");
  const Eigen::Index frames = take.frameCount();
  MarkerColumn column;
  column.label = std::move(label);
  column.positions = Eigen::Matrix<double, Eigen::Dynamic, 3>::Zero(frames, 3);
  column.valid = ValidMask::Constant(frames, true);
  for (Eigen::Index s : sources) {
    column.positions += take.trajectory(s);
    column.valid = column.valid && take.valid().col(s);
  }
  column.positions /= static_cast<double>(sources.size());
  column.residuals = column.valid.select(Eigen::ArrayXd::Zero(frames), Eigen::ArrayXd::Constant(frames, -1.0));
  column.cameraMasks.assign(static_cast<std::size_t>(frames), 0);
  column.states.resize(static_cast<std::size_t>(frames));
  for (Eigen::Index f = 0; f < frames; ++f)
    column.states[static_cast<std::size_t>(f)] = column.valid(f) ? SampleOrigin::Edited : SampleOrigin::Measured;
  return column;
}

SamplePatch validSamplesPatch(const Take& take, Eigen::Index from, Eigen::Index to)
{
  checkMarker(take, from);
  checkMarker(take, to);
  if (from == to)
    throw InvalidArgument("a marker cannot take its own samples");
  SamplePatch patch;
  patch.marker = to;
  for (Eigen::Index f = 0; f < take.frameCount(); ++f)
    if (take.isValid(f, from))
      patch.frames.push_back(f);
  const auto count = static_cast<Eigen::Index>(patch.frames.size());
  patch.positions.resize(count, 3);
  patch.valid = ValidMask::Constant(count, true);
  patch.residuals.resize(count);
  const auto xyz = take.trajectory(from);
  for (Eigen::Index i = 0; i < count; ++i) {
    const Eigen::Index f = patch.frames[static_cast<std::size_t>(i)];
    patch.positions.row(i) = xyz.row(f);
    patch.residuals(i) = take.residuals()(f, from);
    patch.states.push_back(take.state(f, from));
  }
  return patch;
}

std::vector<SamplePatch> swapMarkersOverRange(const Take& take, Eigen::Index a, Eigen::Index b, Eigen::Index first,
                                              Eigen::Index last)
{
  checkMarker(take, a);
  checkMarker(take, b);
  if (a == b)
    throw InvalidArgument("swapping needs two different markers");
  if (first < 0 || last >= take.frameCount() || first > last)
    throw InvalidArgument("frame range " + std::to_string(first) + "-" + std::to_string(last) +
                          " is empty or outside the take (" + std::to_string(take.frameCount()) + " frames)");
  std::vector<SamplePatch> patches;
  patches.push_back(copyRange(take, b, a, first, last));
  patches.push_back(copyRange(take, a, b, first, last));
  return patches;
}

void exchangeMarkersFrom(Take& take, Eigen::Index a, Eigen::Index b, Eigen::Index frame)
{
  checkMarker(take, a);
  checkMarker(take, b);
  if (frame < 0 || frame > take.frameCount())
    throw InvalidArgument("exchange markers: frame " + std::to_string(frame) + " is outside the take (" +
                          std::to_string(take.frameCount()) + " frames)");
  if (a == b || frame == take.frameCount())
    return;
  static_cast<void>(applyPatches(take, swapMarkersOverRange(take, a, b, frame, take.frameCount() - 1)));
}

Take subsetTake(const Take& source, const std::vector<std::string>& labels)
{
  if (labels.empty())
    throw InvalidArgument("a marker subset needs at least one label");
  const std::vector<Eigen::Index> markers = markerIndices(source, labels);
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (std::find(labels.begin(), labels.begin() + static_cast<std::ptrdiff_t>(i), labels[i]) !=
        labels.begin() + static_cast<std::ptrdiff_t>(i))
      throw InvalidArgument("marker '" + labels[i] + "' is named twice in the subset");
  Take take(labels, source.frameCount(), source.frameRate());
  take.setFirstFrame(source.firstFrame());
  take.setUnits(source.units());
  for (Eigen::Index j = 0; j < take.markerCount(); ++j) {
    const Eigen::Index m = markers[static_cast<std::size_t>(j)];
    take.setPointType(j, source.pointType(m));
    take.trajectory(j) = source.trajectory(m);
    take.valid().col(j) = source.valid().col(m);
    take.residuals().col(j) = source.residuals().col(m);
    take.cameraMasks().col(j) = source.cameraMasks().col(m);
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
      take.setState(f, j, source.state(f, m));
  }
  return take;
}

} // namespace mocap
