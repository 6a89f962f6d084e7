#pragma once

#include "mocap/tracking/point_tracker.h"
#include "mocap/model/take.h"

#include <vector>

namespace mocap {

/// Each valid run of each of `markers` as a fragment, markers in the given order: how the
/// unlabelled markers of a C3D ("Unlabeled12", valid only over its fragment) become the
/// labeller's input. Throws InvalidArgument for a marker out of range. O(#frames · #markers).
[[nodiscard]] std::vector<Fragment> fragmentsOfMarkers(const Take& take, const std::vector<Eigen::Index>& markers);

/// Appends the fragments `which` (indices into `fragments`) to the take as unlabelled markers
/// ("Unlabeled1", ...), packed first-fit in order of their first frame so fragments that do not
/// are a frame apart share a marker (so each stays its own valid run). Returns the number of
/// markers added. Throws InvalidArgument when a fragment lies outside the take.
/// O(#fragments · (#added markers + fragment length)).
Eigen::Index appendFragments(Take& take, const std::vector<Fragment>& fragments, const std::vector<Eigen::Index>& which);

/// Copies the point type and every sample (positions, validity, residuals, camera masks, states) of marker `from` of
/// `source` into marker `to` of `target`; both takes must have the same number of frames.
/// Throws InvalidArgument otherwise. O(#frames).
void copyMarker(const Take& source, Eigen::Index from, Take& target, Eigen::Index to);

} // namespace mocap
