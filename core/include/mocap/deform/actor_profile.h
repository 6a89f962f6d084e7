#pragma once

#include "mocap/base/length_unit.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/model/point_set.h"
#include "mocap/model/take.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mocap {

/// One actor's calibration for solving to a rig (per-actor calibration as MetaHuman's neutral
/// frame and Shōgun's subject calibration do it): the actor's neutral marker positions, the
/// binding, and per rig shape the actor's own range. A shape's extent is the actor's full
/// expression as a fraction of the rig's delta at the bound points (1 = as the rig, 0.7 = a jaw
/// that opens to 0.7 of the rig's): solving with the profile reports each rig weight over its
/// extent, so weights come out in the actor's range (1 = the actor's maximum), the equivalent of a
/// gain 1/extent on the rig's weight; with a range-of-motion calibration the solve also undoes its
/// own shrinkage of each expression (BlendshapeSolveOptions::actor).
struct ActorProfile
{
  std::string name;
  LengthUnit units = LengthUnit::Millimetre;  ///< of `neutral` (the takes')
  std::vector<std::string> labels;            ///< the bound markers, binding order
  PointSet neutral;                           ///< #labels × 3: their neutral positions (take units)
  std::string neutralSource;                  ///< where the neutral came from ("TAKE:FRAME" or "TAKE (median)")
  std::vector<std::string> shapes;            ///< the rig's shape names
  Eigen::VectorXd extent;                     ///< per shape, > 0; 1 where not calibrated
  Eigen::VectorXd romMaximum;                 ///< per shape, the range-of-motion take's maximum; NaN without one
  std::string romSource;                      ///< the range-of-motion take, empty without one
  MeshBinding binding;
};

/// Throws InvalidArgument for sizes that disagree, a label or shape named twice, a non-finite
/// neutral coordinate or an extent that is not finite and > 0. O(#labels + #shapes).
void checkActorProfile(const ActorProfile& profile);

/// The profile's neutral positions of `labels` (#labels × 3), matched by label. Throws
/// InvalidArgument naming the first label the profile lacks. O(#labels · #profile labels).
[[nodiscard]] PointSet actorNeutral(const ActorProfile& profile, const std::vector<std::string>& labels);

/// The actor's neutral `neutral` (rows per marker of `markers`) placed where the actor's head is
/// in `take`: the rigid transform from the neutral onto the markers of the take's first frame with
/// the most of them present (`frame` when ≥ 0), fitted by trimmed Kabsch (each of 5 rounds refits
/// on the 60 % of markers nearest their fit, so an expression in that frame moves the fit little:
/// the brow or jaw are left out, the skull's markers kept). Takes recorded apart, or stabilized
/// against another frame, then share the neutral; in the take it was recorded in the transform
/// is the identity up to noise. Throws InvalidArgument when no frame has 3 of the markers.
/// Not a paper equation. O(#frames · #markers) to find the frame, O(#markers · log) per round.
[[nodiscard]] PointSet placeActorNeutral(const Eigen::Ref<const PointSet>& neutral, const Take& take,
                                         const std::vector<Eigen::Index>& markers, Eigen::Index frame = -1);

/// The extents of the rig's `shapes`, matched by name. Throws InvalidArgument naming the first
/// shape the profile lacks (a profile made for another rig). O(#shapes · #profile shapes).
[[nodiscard]] Eigen::VectorXd actorExtents(const ActorProfile& profile, const std::vector<std::string>& shapes);

} // namespace mocap
