#pragma once

#include "mocap/model/marker_set.h"
#include "mocap/tracking/point_tracker.h"
#include "mocap/math/similarity_transform.h"

#include <vector>

namespace mocap {

/// Aligns a template to unlabelled points without correspondences: iterative closest points with
/// a similarity fit (fitSimilarityLoose) of each data point's closest template point onto it (the data
/// may miss markers), pairs within 2.5 × their median distance, from five starts (the centroids
/// matched with the identity rotation and with the four proper rotations taking the template's
/// principal axes onto the points'). The start whose result has the smallest trimmed mean distance
/// (best 75 % of data points to their closest template point) wins; that distance goes to
/// `residual`. Not a paper equation (§2 labels by hand or by the vendor's
/// model). Throws InvalidArgument when either set is empty or not finite.
/// O(starts · iterations · #template · #points).
[[nodiscard]] Similarity alignTemplate(const Eigen::Ref<const PointSet>& templ, const Eigen::Ref<const PointSet>& points,
                                       double* residual = nullptr);

struct LabellingOptions
{
  /// A fragment takes a label only within gateFactor × (the label's nearest template neighbour
  /// distance, scaled to the data) of the label's predicted position; (0, 2].
  double gateFactor = 0.5;
  Eigen::Index neighbours = 6;  ///< labels a prediction is fitted to; 3..100
  Eigen::Index anchorFrame = -1;  ///< where labelling starts; −1: the frame with the most points
};

struct LabellingResult
{
  std::vector<Eigen::Index> labelOf;  ///< per fragment: the marker (index into the take) or −1
  Eigen::Index anchorFrame = -1;
  double anchorResidual = 0.0;  ///< alignTemplate's residual at the anchor (0 when not needed)
  double scale = 1.0;           ///< template-to-data scale found at the anchor
};

/// Gives fragments the labels of `set` (paper §2: labelling after tracking). `take`'s markers
/// 0..#labels−1 are the set's labels in order; samples they already hold (a half-labelled take)
/// are kept and used. At the anchor frame, each free label's position is predicted and the
/// fragments live there are assigned to free labels by assignMinimumCost on squared distance over
/// the label's squared gate; then a sweep forward and one backward label each fragment where it
/// starts (or, backward, ends) the same way. A label's position is predicted from its
/// nearest labelled neighbours (as in gap filling): the rigid motion (kabsch) of ≥ 3 neighbours
/// from the label's last sample in the sweep to now applied to that sample, or, with no usable
/// last sample, the similarity of the neighbours' template positions to their current ones
/// applied to the template position, or, with < 3 labelled markers in the frame, alignTemplate on
/// every point of the frame. A label is free for a fragment only when the take has no sample of
/// it anywhere in the fragment's frames. Assigned fragments are written into the take (valid,
/// residual 0, state Original). Throws InvalidArgument when the take has fewer markers or other
/// frames than needed, a fragment lies outside the take, or options are out of range.
/// O(#frames · #labels + #fragments · (#labels · (neighbours + fragment length) + assignment)).
[[nodiscard]] LabellingResult labelFragments(Take& take, const std::vector<Fragment>& fragments, const MarkerSet& set,
                                             const LabellingOptions& options = {});

} // namespace mocap
