#pragma once

#include "mocap/model/sample_patch.h"
#include "mocap/model/take.h"

#include <Eigen/Geometry>

#include <vector>

namespace mocap {

/// The rigid motion of the head through a take: per frame, the pose mapping the stabilized head
/// (the head as it was in `referenceFrame`) to the captured one, so captured = poses[f] · stabilized.
struct HeadMotion
{
  std::vector<Eigen::Isometry3d> poses;
  /// True where the pose was measured (≥ 3 reference markers valid); false where it was
  /// interpolated between measured neighbours (or held from the nearest one at the take's ends).
  std::vector<bool> known;
  Eigen::Index referenceFrame = 0;
};

/// Estimates the head pose of every frame from head-mounted `referenceMarkers` (indices into the
/// take, ≥ 3, distinct): per frame, the Kabsch fit (kabsch.h) of the reference markers valid in
/// that frame, as they were in `referenceFrame`, onto their captured positions. `referenceFrame`
/// −1 picks the first frame where all reference markers are valid. Frames with fewer than three
/// valid reference markers get a pose interpolated between the nearest measured frames (the
/// reference markers' centre on a straight line, the rotation by slerp), or the nearest measured
/// pose before the first / after the last one, and known = false. Not a paper equation: the
/// paper restricts head motion at capture time (§5.1); this removes it in software so
/// neighbour-based recovery (eqs 3-7) sees facial motion only. Throws InvalidArgument for fewer
/// than three or repeated or out-of-range markers, a reference point that is a model output, an
/// empty take, a reference frame out of range
/// or with an invalid reference marker, no frame where all are valid, or a non-finite valid
/// reference sample. O(#frames · #referenceMarkers).
[[nodiscard]] HeadMotion estimateHeadMotion(const Take& take,
                                            const std::vector<Eigen::Index>& referenceMarkers,
                                            Eigen::Index referenceFrame = -1);

/// Maps every marker sample (valid or not; validity untouched; model outputs are left alone,
/// marker_points.h) into the stabilized head frame: p ← poses[f]⁻¹ · p. Valid samples gain
/// SampleOperation::Stabilized (their origin stays). Throws InvalidArgument unless motion has one
/// pose per frame.
/// Not a paper equation. O(#frames · #markers).
void removeHeadMotion(Take& take, const HeadMotion& motion);

/// The exact inverse of removeHeadMotion (up to rounding): p ← poses[f] · p; every sample loses
/// SampleOperation::Stabilized (its value is back in the capture frame). Throws InvalidArgument unless motion has one pose per frame. Not a paper equation.
/// O(#frames · #markers).
void restoreHeadMotion(Take& take, const HeadMotion& motion);

/// The head-mounted reference markers to propose (a default for the user to confirm): the markers
/// whose labels start with "root" or "head" (any case), the usual names, when there are at least
/// three; else headSizedRigidCluster(take). Empty when neither finds three. O(#markers) by label,
/// else as mostRigidCluster.
[[nodiscard]] std::vector<Eigen::Index> guessHeadReferenceMarkers(const Take& take);

struct RigidClusterOptions
{
  /// The largest strain of a distance between two markers of the cluster (its standard
  /// deviation over its mean): head-mounted markers keep theirs to their capture noise (the
  /// sample's root-1…4: at most 0.5 %, root-5 and root-6 up to 1.5 %), while a skin marker moving
  /// a few millimetres on the face strains by several percent.
  double tolerance = 0.01;
  /// Frames sampled, evenly spaced over the take, to measure the distances on.
  Eigen::Index maxFrames = 300;
};

/// The largest group of markers that moves as one rigid body: every pairwise distance keeps a
/// strain (standard deviation / mean) ≤ tolerance over the sampled frames where both are valid. Only labelled
/// marker points (no model outputs) (not isUnlabelledLabel) valid in at least half the frames are considered. Greedy:
/// starts from the most rigid pair and adds the marker whose worst spread to the cluster is least,
/// while it is within the tolerance. Returns marker indices in take order, or nothing when fewer
/// than three markers qualify (three are needed for a pose). Not a paper equation: a default for
/// takes whose head markers are not named. Throws InvalidArgument for tolerance ≤ 0 or
/// maxFrames < 2. O(#markers² · #sampled frames + #markers³).
[[nodiscard]] std::vector<Eigen::Index> mostRigidCluster(const Take& take, const RigidClusterOptions& options = {});

/// mostRigidCluster(take) when it can be a head's: a face take's markers stay within a head's
/// reach of it (most of them within 300 mm of its centre, the median over sampled frames), while
/// on a full-body take the most rigid cluster is a pelvis or a limb's and most markers are far
/// from it (Vicon's gait-pig: 4 pelvis markers, the feet a metre away). Empty otherwise, so no
/// head markers are proposed for a body take. Not a paper equation. O(as mostRigidCluster).
[[nodiscard]] std::vector<Eigen::Index> headSizedRigidCluster(const Take& take);

/// removeHeadMotion as patches (one per marker point, every frame): the studio previews and undoes
/// stabilization like any other edit. Validity, residuals and origins are kept (the samples move,
/// they are not re-measured); valid samples gain SampleOperation::Stabilized. Throws
/// InvalidArgument unless motion has one pose per frame.
/// O(#frames · #markers).
[[nodiscard]] std::vector<SamplePatch> headMotionRemovalPatches(const Take& take, const HeadMotion& motion);

} // namespace mocap
