#pragma once
// What the marker selection methods and the layout plan check and share about their inputs: the
// symmetry's size, the training frames, and the symmetric units a selection is made of. Private
// to core/src/layout.

#include "mocap/model/marker_pairs.h"

#include <Eigen/Core>

#include <vector>

namespace mocap::layout_internal {

// Throws InvalidArgument unless `symmetry` covers `markers` markers. O(1).
void checkSymmetry(const MarkerSymmetry& symmetry, Eigen::Index markers);

// Throws InvalidArgument unless `training` holds at least two markers (3 columns each) and only
// finite values. O(size).
void checkTraining(const Eigen::Ref<const Eigen::MatrixXd>& training);

// The markers of the selected units (selected[u]: unit u of symmetry.units()), sorted. O(#markers).
[[nodiscard]] std::vector<Eigen::Index> markersOfUnits(const MarkerSymmetry& symmetry, const std::vector<bool>& selected);

// Whether whole units (pairs and singles) can make exactly `size` markers. O(#units).
[[nodiscard]] bool sizeReachable(const MarkerSymmetry& symmetry, Eigen::Index size);

} // namespace mocap::layout_internal
