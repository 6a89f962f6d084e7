#pragma once

#include "mocap/model/marker_pairs.h"
#include "mocap/model/point_set.h"
#include "mocap/model/take.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mocap {

using LabelPair = std::pair<Eigen::Index, Eigen::Index>;

/// A marker set: the labels of a layout with a neutral (template) position each, the left/right
/// pairs PFA symmetry uses, links the 3D view draws, and an optional binding of markers to mesh
/// vertices for deformation. One file (marker_set_io.h) serves all of them.
struct MarkerSet
{
  std::vector<std::string> labels;
  /// Template positions, one row per label, in `units`; the labeller aligns these to the data.
  PointSet neutral;
  LengthUnit units = LengthUnit::Millimetre;
  std::vector<LabelPair> pairs;  ///< left/right mirror partners (indices into labels)
  std::vector<LabelPair> links;  ///< segments to draw between markers
  std::string meshFile;          ///< mesh the binding refers to; empty when there is none
  std::vector<Eigen::Index> meshVertices;  ///< empty, or one vertex per label (−1 = unbound)

  [[nodiscard]] Eigen::Index size() const { return static_cast<Eigen::Index>(labels.size()); }
  /// The pairs as a MarkerSymmetry (validated there).
  [[nodiscard]] MarkerSymmetry symmetry() const { return MarkerSymmetry(size(), pairs); }
};

/// Throws InvalidArgument naming the problem: no labels, a repeated or empty label, a neutral
/// table of the wrong size or with a non-finite entry, a pair or link index out of range or
/// joining a marker to itself, a marker in two pairs, or a mesh binding of the wrong size or with
/// a vertex below −1. O(#labels log #labels + #pairs + #links).
void validateMarkerSet(const MarkerSet& set);

/// True for labels capture software gives to points it could not label: "Unlabeled12",
/// "Unlabelled 3", "unlabeled", "*17" (case-insensitive). O(length).
[[nodiscard]] bool isUnlabelledLabel(std::string_view label);

/// The frame where most of `markers` are valid (the first such frame): the neutral frame a
/// template is taken from. −1 when none is ever valid. O(#frames · #markers).
[[nodiscard]] Eigen::Index mostCompleteFrame(const Take& take, const std::vector<Eigen::Index>& markers);
/// The same over the take's marker points (marker_points.h: no model outputs).
[[nodiscard]] Eigen::Index mostCompleteFrame(const Take& take);

/// A marker set from a labelled take: its labelled markers (isUnlabelledLabel ones, model outputs
/// and markers never valid are left out), their positions in `frame` (−1: mostCompleteFrame) or, for a marker
/// invalid there, in its nearest valid frame; pairs from detectMarkerPairs; links from each marker
/// to its two nearest neighbours in the template. Throws InvalidArgument when the take has no
/// labelled marker with a valid sample or `frame` is out of range. O(#frames · #markers + #markers²).
[[nodiscard]] MarkerSet markerSetFromTake(const Take& take, Eigen::Index frame = -1);

} // namespace mocap
