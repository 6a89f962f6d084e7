#pragma once

#include "mocap/model/blendshape_rig.h"

#include <Eigen/Core>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mocap {

/// The rig as glTF 2.0 binary (GLB): the neutral mesh (positions and triangles), one morph target
/// per shape — sparse accessors holding only the moved vertices — named in the mesh's
/// `extras.targetNames` (which Blender, three.js and Unity read as shape-key names), and, when
/// `weights` has rows, an animation of the node's `weights` path with one key per frame (frame i
/// at i / frameRate seconds, linear interpolation), or at the frames `keys` only when it is not
/// empty (ascending from the first frame to the last: reduceKeys' choice, which all shapes share,
/// as glTF's one weights sampler requires). glTF has no start time: `startSeconds`, when given
/// (a Live Link Face recording's start timecode, as FBX keeps it), is kept in the animation's
/// `extras.startSeconds` (seconds, a number); the keys still start at 0. Coordinates are written as
/// float32 in the rig's units. Throws InvalidArgument for an invalid rig (checkRig), weights with
/// another column count or outside a finite range, a non-positive rate, or a start time that is
/// negative or not finite. O(#vertices + Σ #moved + #frames · #shapes).
[[nodiscard]] std::string rigGlb(const BlendshapeRig& rig, const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                 double frameRate, const std::vector<Eigen::Index>& keys = {},
                                 std::optional<double> startSeconds = std::nullopt);

/// Writes rigGlb atomically. Throws as rigGlb and IoError.
void writeRigGlb(const std::filesystem::path& path, const BlendshapeRig& rig,
                 const Eigen::Ref<const Eigen::MatrixXd>& weights, double frameRate,
                 const std::vector<Eigen::Index>& keys = {}, std::optional<double> startSeconds = std::nullopt);

} // namespace mocap
