#pragma once

#include "mocap/model/mesh.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// One named shape of a blendshape rig as a sparse delta from the neutral: only the vertices that
/// move (a facial shape moves a few thousand of tens of thousands), each with its displacement.
struct SparseShape
{
  std::string name;
  std::vector<Eigen::Index> vertices;  ///< ascending
  MeshVertices deltas;                 ///< one row per entry of `vertices`, mesh units

  [[nodiscard]] Eigen::Index size() const { return static_cast<Eigen::Index>(vertices.size()); }
  /// The delta of `vertex` (zero where the shape does not move it). O(log #moved vertices).
  [[nodiscard]] Eigen::Vector3d deltaOf(Eigen::Index vertex) const;
};

/// A neutral mesh plus named shapes of the same topology: face = neutral + Σₛ wₛ·Δₛ with
/// 0 ≤ wₛ ≤ 1 (the semantic rig animators key, ARKit-style names such as jawOpen, mouthSmile_L).
struct BlendshapeRig
{
  Mesh neutral;
  std::vector<SparseShape> shapes;

  [[nodiscard]] Eigen::Index shapeCount() const { return static_cast<Eigen::Index>(shapes.size()); }
  [[nodiscard]] std::vector<std::string> shapeNames() const;
  /// The index of the shape called `name`, if any. O(#shapes).
  [[nodiscard]] std::optional<Eigen::Index> shapeIndex(std::string_view name) const;
  /// neutral + Σₛ weights(s)·Δₛ into `out` (#vertices × 3). Throws InvalidArgument for a weight
  /// vector of the wrong size. O(#vertices + Σ #moved vertices).
  void evaluate(const Eigen::Ref<const Eigen::VectorXd>& weights, MeshVertices& out) const;
};

/// The sparse delta of `shape` (the posed vertices, same count as `neutral`) from `neutral`:
/// vertices whose displacement exceeds `tolerance` (mesh units) in some axis. Throws
/// InvalidArgument for a vertex count that differs or a non-finite coordinate. O(#vertices).
[[nodiscard]] SparseShape sparseShape(std::string name, const Eigen::Ref<const MeshVertices>& neutral,
                                      const Eigen::Ref<const MeshVertices>& shape, double tolerance);

/// Throws InvalidArgument unless the neutral is a valid mesh (checkMesh), there is at least one
/// shape, the names are non-empty and distinct, and every shape's vertices are ascending, in range
/// and have finite deltas. O(#vertices + Σ #moved vertices + #shapes · log #shapes).
void checkRig(const BlendshapeRig& rig);

/// The rig with only the shapes called `names`, in that order. Throws InvalidArgument for a name
/// the rig does not have or a name given twice. O(#names · #shapes).
[[nodiscard]] BlendshapeRig selectShapes(const BlendshapeRig& rig, const std::vector<std::string>& names);

/// The rig cut to the contiguous vertex range first…last (e.g. ICT FaceKit's face, 0…9408),
/// renumbered from 0: the faces whose vertices all lie inside, each shape's entries inside. The
/// UV and normal tables are kept whole (faces keep their indices into them; some may go unused).
/// Throws InvalidArgument for an empty range, one outside the mesh, or one that leaves no face.
/// O(#corners + #vertices + Σ #moved vertices).
[[nodiscard]] BlendshapeRig rigRegion(const BlendshapeRig& rig, Eigen::Index first, Eigen::Index last);

/// The rig without the shape entries that move no axis more than `tolerance` (mesh units), the
/// test sparseShape applies: for a smaller file when sub-micron motion does not matter. Throws
/// InvalidArgument for a negative or non-finite tolerance. O(Σ #moved vertices).
[[nodiscard]] BlendshapeRig prunedRig(const BlendshapeRig& rig, double tolerance);

} // namespace mocap
