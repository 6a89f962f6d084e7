#pragma once

#include "mocap/base/job_control.h"
#include "mocap/deform/actor_profile.h"
#include "mocap/model/blendshape_rig.h"
#include "mocap/model/take.h"

#include <string>
#include <vector>

namespace mocap {

/// The positions of `labels` in frame `frameNumber` (as the take numbers frames) of a neutral
/// take (#labels × 3). Throws InvalidArgument for a label the take lacks, a frame outside the
/// take, or markers missing in that frame (naming them all). O(#labels · #markers).
[[nodiscard]] PointSet neutralFromFrame(const Take& take, const std::vector<std::string>& labels,
                                        long long frameNumber);

/// Per marker of `labels` the coordinate-wise median over the frames where it is present: a
/// neutral take held for a while, robust to the odd blink or twitch. Throws InvalidArgument for
/// a label the take lacks or a marker present in no frame. O(#labels · #frames · log #frames).
[[nodiscard]] PointSet neutralFromTake(const Take& take, const std::vector<std::string>& labels);

/// A profile of the actor with `neutral` (binding order, `units`), every extent 1 and no
/// range-of-motion maxima. Throws as checkActorProfile. O(#markers + #shapes).
[[nodiscard]] ActorProfile makeActorProfile(std::string name, const MeshBinding& binding, const BlendshapeRig& rig,
                                            const PointSet& neutral, LengthUnit units, std::string neutralSource);

struct ActorRangeOptions
{
  /// The upper bound of the calibration solve, well above 1, so that a shape the actor
  /// exaggerates is measured rather than clipped.
  double maximumWeight = 4.0;
  /// A shape whose maximum stays below this was not clearly reached: it keeps extent 1.
  double reachedWeight = 0.2;
  /// The maximum is taken over the running median of this many frames, so a one-frame spike of
  /// noise does not set a shape's range (a range-of-motion take holds each peak for a moment).
  int window = 5;
};

/// What calibration found per shape (the profile's shape order).
struct ActorRange
{
  Eigen::VectorXd maximum;     ///< the shape's maximum in the range-of-motion take, as a fraction of the rig's delta
  std::vector<bool> reached;   ///< maximum ≥ reachedWeight: its extent was set
  std::vector<bool> clipped;   ///< the maximum reached the solve's upper bound: not measured, extent 1
};

/// Calibrates the actor's range from a range-of-motion take (the same markers, in the profile's
/// units, in the frame the binding was made in): the take is solved against the profile's
/// neutral with extents 1, per frame by bounded least squares without ridge and with weights up
/// to `options.maximumWeight`, so neither the [0, 1] box nor ridge/GCV shrinkage biases a shape
/// solved alone (a gain of 1 / the maximum of the usual solve overcorrects: that solve shrinks an
/// isolated shape far more than one in a performance). Each reached shape's extent becomes its
/// maximum (over the running median of `options.window` frames); the others, and those at the
/// bound (most likely shapes the markers cannot see), keep extent 1.
/// Sets profile.extent, romMaximum and romSource. Not a paper equation. Throws InvalidArgument for
/// a take missing bound markers (another marker set), in other units, or a rig whose shapes are
/// not the profile's. O(the blendshape solve's bvls cost + #frames · #shapes · window).
ActorRange calibrateActorRange(ActorProfile& profile, const BlendshapeRig& rig, const Take& rom,
                               const std::string& romSource, const ActorRangeOptions& options = {},
                               const JobControl& control = {});

} // namespace mocap
