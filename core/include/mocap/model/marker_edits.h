#pragma once

#include "mocap/model/sample_patch.h"
#include "mocap/model/take.h"

#include <string>
#include <vector>

namespace mocap {

/// Edits a technician makes to whole markers (the studio's marker menu), each returned as data
/// the caller puts in through an undoable step (SamplePatch or Take::insertMarker).

/// A virtual marker at the mean of `sources` in every frame where all of them are valid
/// (invalid elsewhere, residual −1), residual 0 and state Edited where valid, labelled `label`.
/// Used for a marker that was never placed (e.g. the midpoint of two eye corners) or to stand in
/// for one that is lost. Throws InvalidArgument for no sources, an index outside the take or a
/// repeated source. O(#frames · #sources).
[[nodiscard]] MarkerColumn averagedMarker(const Take& take, const std::vector<Eigen::Index>& sources,
                                          std::string label);

/// Patches that exchange everything markers `a` and `b` hold over frames [first, last]
/// (positions, validity, residuals, states, camera masks): the fix for two labels swapped by the tracker after
/// the markers crossed. Apply both (applyPatches); applying the undo patches swaps back. Throws
/// InvalidArgument when a == b, an index is outside the take or the range is empty or outside it.
/// O(last − first).
[[nodiscard]] std::vector<SamplePatch> swapMarkersOverRange(const Take& take, Eigen::Index a, Eigen::Index b,
                                                            Eigen::Index first, Eigen::Index last);

/// swapMarkersOverRange from `frame` to the end of the take, applied in place: the repair of one
/// label swap (applying it twice restores the take); a == b or frame == #frames changes nothing.
/// Throws InvalidArgument for a marker or frame outside the take. O(#frames − frame).
void exchangeMarkersFrom(Take& take, Eigen::Index a, Eigen::Index b, Eigen::Index frame);

/// A patch that gives marker `to` every valid sample of marker `from` (position, residual,
/// state), overwriting `to` in those frames: how a hand-labelled fragment joins its marker
/// (remove `from` afterwards). Empty when `from` has no valid sample. Throws InvalidArgument for
/// an index outside the take or from == to. O(#frames).
[[nodiscard]] SamplePatch validSamplesPatch(const Take& take, Eigen::Index from, Eigen::Index to);

/// A take holding only the markers `labels` of `source`, in that order, with their point types,
/// every frame and each sample's position, validity, residual, camera mask and state: a capture reduced to a
/// planned marker layout. Frame rate, first frame and units are kept; analog data, events and
/// C3D parameters are not (they describe the full capture). Throws InvalidArgument for no
/// labels, a label `source` does not have or a label given twice. O(#frames · #labels).
[[nodiscard]] Take subsetTake(const Take& source, const std::vector<std::string>& labels);

} // namespace mocap
