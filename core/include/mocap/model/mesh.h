#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace mocap {

/// Vertex positions of a mesh, one row per vertex (row-major so a frame is one contiguous block,
/// as point caches store it).
using MeshVertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// One polygon: vertex indices (≥ 3) and, when the file had them, the matching UV and normal
/// indices (same length, or empty).
struct MeshFace
{
  std::vector<Eigen::Index> vertices;
  std::vector<Eigen::Index> uvs;
  std::vector<Eigen::Index> normals;
};

using Triangle = std::array<Eigen::Index, 3>;

/// A polygon mesh as the OBJ and PLY readers give it: triangles and quads (any polygon) are kept
/// as they are, so an export writes the same faces, UVs and normals back.
struct Mesh
{
  MeshVertices vertices;
  Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> uvs;
  MeshVertices normals;
  std::vector<MeshFace> faces;

  [[nodiscard]] Eigen::Index vertexCount() const { return vertices.rows(); }
  /// Every face split into a fan of triangles (v0, vi, vi+1). O(#corners).
  [[nodiscard]] std::vector<Triangle> triangles() const;
  /// Length of the bounding-box diagonal (0 for no vertices): the mesh's size for tolerances. O(#vertices).
  [[nodiscard]] double size() const;
};

/// Throws InvalidArgument unless every face has ≥ 3 distinct vertices in range, UV and normal
/// indices in range (or none), and every coordinate is finite. O(#corners + #vertices).
void checkMesh(const Mesh& mesh);

} // namespace mocap
