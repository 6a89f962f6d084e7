#include "mocap/model/sample_patch.h"

#include "mocap/base/error.h"

#include <algorithm>

namespace mocap {

namespace {
void checkPatch(const Take& take, const SamplePatch& patch)
{
  const auto n = static_cast<Eigen::Index>(patch.frames.size());
  if (patch.positions.rows() != n || patch.valid.size() != n || patch.residuals.size() != n ||
      static_cast<Eigen::Index>(patch.states.size()) != n ||
      (!patch.cameraMasks.empty() && static_cast<Eigen::Index>(patch.cameraMasks.size()) != n))
    throw InvalidArgument("sample patch arrays disagree in size");
  if (patch.marker < 0 || patch.marker >= take.markerCount())
    throw InvalidArgument("sample patch marker " + std::to_string(patch.marker) + " out of range");
  for (std::size_t i = 0; i < patch.frames.size(); ++i) {
    const Eigen::Index f = patch.frames[i];
    if (f < 0 || f >= take.frameCount() || (i > 0 && f <= patch.frames[i - 1]))
      throw InvalidArgument("sample patch frames must be ascending indices inside the take");
  }
}
} // namespace

SamplePatch makePatch(Eigen::Index marker, std::vector<Eigen::Index> frames,
                      Eigen::Matrix<double, Eigen::Dynamic, 3> positions, SampleState state)
{
  const auto n = static_cast<Eigen::Index>(frames.size());
  if (positions.rows() != n)
    throw InvalidArgument("a patch needs one position per frame");
  SamplePatch patch;
  patch.marker = marker;
  patch.frames = std::move(frames);
  patch.positions = std::move(positions);
  patch.valid = Eigen::Array<bool, Eigen::Dynamic, 1>::Constant(n, true);
  patch.residuals = Eigen::ArrayXd::Zero(n);
  patch.states.assign(static_cast<std::size_t>(n), state);
  return patch;
}

SamplePatch deleteSamples(const Take& take, Eigen::Index marker, Eigen::Index first, Eigen::Index last)
{
  if (marker < 0 || marker >= take.markerCount())
    throw InvalidArgument("marker " + std::to_string(marker) + " out of range");
  if (first < 0 || last >= take.frameCount() || first > last)
    throw InvalidArgument("frame range " + std::to_string(first) + "-" + std::to_string(last) + " is not inside the take");
  std::vector<Eigen::Index> frames;
  for (Eigen::Index f = first; f <= last; ++f)
    if (take.isValid(f, marker))
      frames.push_back(f);
  const auto n = static_cast<Eigen::Index>(frames.size());
  SamplePatch patch;
  patch.marker = marker;
  patch.positions.resize(n, 3);
  for (Eigen::Index i = 0; i < n; ++i)
    patch.positions.row(i) = take.position(frames[static_cast<std::size_t>(i)], marker).transpose();
  patch.frames = std::move(frames);
  patch.valid = Eigen::Array<bool, Eigen::Dynamic, 1>::Constant(n, false);
  patch.residuals = Eigen::ArrayXd::Constant(n, -1.0);
  patch.states.assign(static_cast<std::size_t>(n), SampleState(SampleOrigin::Edited));
  return patch;
}

SamplePatch swapSamples(Take& take, SamplePatch patch)
{
  checkPatch(take, patch);  // every frame inside the take, so the loop indexes unchecked
  const Eigen::Index m = patch.marker;
  auto trajectory = take.trajectory(m);
  auto valid = take.valid().col(m);
  auto residuals = take.residuals().col(m);
  auto states = take.states().col(m);
  auto masks = take.cameraMasks().col(m);
  const bool withMasks = !patch.cameraMasks.empty();
  for (std::size_t i = 0; i < patch.frames.size(); ++i) {
    const Eigen::Index f = patch.frames[i];
    const auto row = static_cast<Eigen::Index>(i);
    for (Eigen::Index c = 0; c < 3; ++c)
      std::swap(trajectory(f, c), patch.positions(row, c));
    std::swap(valid(f), patch.valid(row));
    std::swap(residuals(f), patch.residuals(row));
    const std::uint8_t state = patch.states[i].bits();
    patch.states[i] = SampleState::fromBits(states(f));
    states(f) = state;
    if (withMasks)
      std::swap(masks(f), patch.cameraMasks[i]);
  }
  return patch;
}

std::vector<SamplePatch> applyPatches(Take& take, std::vector<SamplePatch> patches)
{
  std::vector<SamplePatch> undo;
  undo.reserve(patches.size());
  for (auto& patch : patches)
    undo.push_back(swapSamples(take, std::move(patch)));
  std::reverse(undo.begin(), undo.end());
  return undo;
}

SamplePatch patchWithin(const SamplePatch& patch, Eigen::Index first, Eigen::Index last)
{
  std::vector<Eigen::Index> rows;
  for (std::size_t i = 0; i < patch.frames.size(); ++i)
    if (patch.frames[i] >= first && patch.frames[i] <= last)
      rows.push_back(static_cast<Eigen::Index>(i));
  SamplePatch part;
  part.marker = patch.marker;
  part.positions = patch.positions(rows, Eigen::all);
  part.valid = patch.valid(rows);
  part.residuals = patch.residuals(rows);
  for (const Eigen::Index row : rows) {
    part.frames.push_back(patch.frames[static_cast<std::size_t>(row)]);
    part.states.push_back(patch.states[static_cast<std::size_t>(row)]);
    if (!patch.cameraMasks.empty())
      part.cameraMasks.push_back(patch.cameraMasks[static_cast<std::size_t>(row)]);
  }
  return part;
}

} // namespace mocap
