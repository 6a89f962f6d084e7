#pragma once

#include "mocap/io/fbx_document.h"
#include "mocap/math/key_reduction.h"
#include "mocap/model/blendshape_rig.h"
#include "mocap/model/take.h"

#include <Eigen/Core>

#include <filesystem>
#include <optional>
#include <string>

namespace mocap {

/// How an FBX writer keys its curves: every frame, or with a `tolerance` each curve on its own
/// keeps the fewest keys whose linear interpolation stays near every frame (reduceKeys): a
/// shape's DeformPercent within the tolerance of the weight, a marker's X, Y and Z each within
/// tolerance / √3, so the marker stays within the tolerance in 3-D; a constant curve (Visibility)
/// keys only its changes. `counted`, when given, receives the keys before and after (translation
/// and DeformPercent curves) and the largest error (a marker's 3-D distance, a weight's).
struct FbxCurveKeys
{
  std::optional<double> tolerance;  ///< the take's units for markers, weight units (0…1) for shapes
  KeyCount* counted = nullptr;
};

/// The take's markers as a binary FBX 7.4 scene for animation tools: a root null "Markers" at the
/// origin with one null per marker (Model "Null", named by its label) whose Lcl Translation is
/// animated with one linear key per frame (frame i at i / rate seconds), in the take's units,
/// which GlobalSettings declares with `up`. FBX curves have no gaps: in a gap a marker holds the
/// position of its nearest valid sample in time (the earlier one on a tie, as the BVH writer
/// does), and a marker with gaps also gets a Visibility curve, 0 (constant keys) in its gaps and 1
/// elsewhere; a marker never valid has no curves and Visibility 0. Model outputs are left out
/// (leftOutOnWriting says so). With `keys.tolerance`, curves are reduced (FbxCurveKeys). Throws
/// InvalidArgument for a take with only model outputs or a negative or non-finite tolerance.
/// O(#frames · #markers), times reduceKeys' reach with a tolerance.
[[nodiscard]] std::string markersFbx(const Take& take, FbxUpAxis up, const FbxCurveKeys& keys = {});

/// Writes markersFbx atomically. Throws as markersFbx and IoError (the previous file is kept).
void writeMarkersFbx(const std::filesystem::path& path, const Take& take, FbxUpAxis up,
                     const FbxCurveKeys& keys = {});

/// How the solved rig's FBX declares its coordinates: the rig's own units and up axis (the
/// coordinates are written as they are).
struct FbxRigOptions
{
  FbxUpAxis up = FbxUpAxis::Y;
  LengthUnit unit = LengthUnit::Centimetre;
  FbxCurveKeys keys;  ///< every frame, or reduced DeformPercent curves (tolerance in weight units)
  double startSeconds = 0.0;  ///< the first frame's time (a Live Link recording's timecode), 0 for a solve
};

/// The rig as a binary FBX 7.4 skeletal mesh with morph curves, the layout Unreal, Blender, Maya
/// and MotionBuilder import: a mesh "Face" (the neutral's polygons as they are) skinned with
/// weight 1 to one root bone "root" (LimbNode, a Skin with one Cluster and a bind pose, all
/// identity), a BlendShape deformer with one BlendShapeChannel and one Shape per rig shape, both
/// named exactly as the shape, the Shape sparse as in the rig (Indexes and their deltas), and when
/// `weights` has rows one DeformPercent curve per channel: weight × 100, one linear key per frame
/// (frame i at startSeconds + i / frameRate seconds) or reduced as options.keys says. Throws
/// InvalidArgument for an invalid rig (checkRig),
/// weights with another column count or not finite, or a non-positive rate.
/// O(#vertices + #corners + Σ #moved + #frames · #shapes).
[[nodiscard]] std::string rigFbx(const BlendshapeRig& rig, const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                 double frameRate, const FbxRigOptions& options);

/// Writes rigFbx atomically. Throws as rigFbx and IoError (the previous file is kept).
void writeRigFbx(const std::filesystem::path& path, const BlendshapeRig& rig,
                 const Eigen::Ref<const Eigen::MatrixXd>& weights, double frameRate, const FbxRigOptions& options);

} // namespace mocap
