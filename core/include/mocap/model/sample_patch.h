#pragma once

#include "mocap/model/take.h"

#include <cstdint>
#include <vector>

namespace mocap {

/// New contents for some samples of one marker: the unit every edit (spike replacement, gap
/// fill, smoothing, a hand edit) produces, so the studio can preview it without touching the
/// take and undo it exactly. Rows of `positions`, `valid`, `residuals` and `states` follow
/// `frames` (0-based frame indices, ascending, no repeats).
struct SamplePatch
{
  Eigen::Index marker = 0;
  std::vector<Eigen::Index> frames;
  Eigen::Matrix<double, Eigen::Dynamic, 3> positions;
  Eigen::Array<bool, Eigen::Dynamic, 1> valid;
  Eigen::ArrayXd residuals;
  std::vector<SampleState> states;
  /// The samples' camera masks, or empty to leave the take's as they are (only an exchange of
  /// two markers' samples moves them; every other edit keeps which cameras saw the marker).
  std::vector<std::uint8_t> cameraMasks;

  [[nodiscard]] std::size_t size() const { return frames.size(); }
  [[nodiscard]] bool empty() const { return frames.empty(); }
};

/// A patch that makes `frames` of `marker` valid at `positions` (one row per frame) with
/// residual 0 and the given state (an origin: the new values replace whatever was done before). Throws InvalidArgument when the sizes disagree.
[[nodiscard]] SamplePatch makePatch(Eigen::Index marker, std::vector<Eigen::Index> frames,
                                    Eigen::Matrix<double, Eigen::Dynamic, 3> positions, SampleState state);

/// A patch that makes frames [first, last] of `marker` a gap (invalid, residual −1, origin
/// Edited), keeping their positions. Frames already invalid are left out. Throws
/// InvalidArgument for a marker or range outside the take. O(last − first).
[[nodiscard]] SamplePatch deleteSamples(const Take& take, Eigen::Index marker, Eigen::Index first, Eigen::Index last);

/// The part of `patch` on frames [first, last] (possibly empty). O(patch size).
[[nodiscard]] SamplePatch patchWithin(const SamplePatch& patch, Eigen::Index first, Eigen::Index last);

/// Puts `patch` into `take` and returns the samples it replaced, so applying the returned patch
/// undoes the edit bit for bit. Throws InvalidArgument (and changes nothing) when the patch does
/// not fit the take. O(patch size).
SamplePatch swapSamples(Take& take, SamplePatch patch);

/// Applies every patch in order; returns the undo patches in reverse order (apply them in the
/// returned order to undo). O(total patch size).
std::vector<SamplePatch> applyPatches(Take& take, std::vector<SamplePatch> patches);

} // namespace mocap
