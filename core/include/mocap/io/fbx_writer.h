#pragma once

#include "mocap/io/fbx_document.h"
#include "mocap/model/blendshape_rig.h"
#include "mocap/model/take.h"

#include <Eigen/Core>

#include <filesystem>
#include <string>

namespace mocap {

/// The take's markers as a binary FBX 7.4 scene for animation tools: a root null "Markers" at the
/// origin with one null per marker (Model "Null", named by its label) whose Lcl Translation is
/// animated with one linear key per frame (frame i at i / rate seconds), in the take's units,
/// which GlobalSettings declares with `up`. FBX curves have no gaps: in a gap a marker holds the
/// position of its nearest valid sample in time (the earlier one on a tie, as the BVH writer
/// does), and a marker with gaps also gets a Visibility curve, 0 (constant keys) in its gaps and 1
/// elsewhere; a marker never valid has no curves and Visibility 0. Model outputs are left out
/// (leftOutOnWriting says so). Throws InvalidArgument for a take with only model outputs.
/// O(#frames · #markers).
[[nodiscard]] std::string markersFbx(const Take& take, FbxUpAxis up);

/// Writes markersFbx atomically. Throws as markersFbx and IoError (the previous file is kept).
void writeMarkersFbx(const std::filesystem::path& path, const Take& take, FbxUpAxis up);

/// How the solved rig's FBX declares its coordinates: the rig's own units and up axis (the
/// coordinates are written as they are).
struct FbxRigOptions
{
  FbxUpAxis up = FbxUpAxis::Y;
  LengthUnit unit = LengthUnit::Centimetre;
  double startSeconds = 0.0;  ///< the first frame's time (a Live Link recording's timecode), 0 for a solve
};

/// The rig as a binary FBX 7.4 skeletal mesh with morph curves, the layout Unreal, Blender, Maya
/// and MotionBuilder import: a mesh "Face" (the neutral's polygons as they are) skinned with
/// weight 1 to one root bone "root" (LimbNode, a Skin with one Cluster and a bind pose, all
/// identity), a BlendShape deformer with one BlendShapeChannel and one Shape per rig shape, both
/// named exactly as the shape, the Shape sparse as in the rig (Indexes and their deltas), and when
/// `weights` has rows one DeformPercent curve per channel: weight × 100, one linear key per frame
/// (frame i at startSeconds + i / frameRate seconds). Throws InvalidArgument for an invalid rig (checkRig),
/// weights with another column count or not finite, or a non-positive rate.
/// O(#vertices + #corners + Σ #moved + #frames · #shapes).
[[nodiscard]] std::string rigFbx(const BlendshapeRig& rig, const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                 double frameRate, const FbxRigOptions& options);

/// Writes rigFbx atomically. Throws as rigFbx and IoError (the previous file is kept).
void writeRigFbx(const std::filesystem::path& path, const BlendshapeRig& rig,
                 const Eigen::Ref<const Eigen::MatrixXd>& weights, double frameRate, const FbxRigOptions& options);

} // namespace mocap
