#pragma once

#include "mocap/model/mesh.h"
#include "mocap/math/similarity_transform.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace mocap {

class JsonValue;
class JsonWriter;

/// A point on a mesh as barycentric weights of three vertices (a vertex itself: {v, v, v} with
/// weights (1, 0, 0)), so it follows the mesh when the vertices move.
struct MeshPoint
{
  Triangle vertices{};
  Eigen::Vector3d weights = Eigen::Vector3d(1.0, 0.0, 0.0);

  [[nodiscard]] static MeshPoint atVertex(Eigen::Index v) { return {{v, v, v}, Eigen::Vector3d(1.0, 0.0, 0.0)}; }
  [[nodiscard]] bool isVertex() const { return weights(0) == 1.0 && weights(1) == 0.0 && weights(2) == 0.0; }
  /// Σ wₖ·vertices(iₖ). O(1).
  [[nodiscard]] Eigen::Vector3d on(const Eigen::Ref<const MeshVertices>& vertices) const;
};

/// The point of triangle (a, b, c) closest to `query`, as barycentric weights (Ericson,
/// Real-Time Collision Detection §5.1.5: Voronoi regions of vertices, edges and face). A
/// degenerate triangle gives the closest of its vertices and edges. O(1).
[[nodiscard]] Eigen::Vector3d closestTriangleWeights(const Eigen::Vector3d& query, const Eigen::Vector3d& a,
                                                     const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// The surface point of `triangles` closest to `query`, and its distance. Brute force over the
/// triangles, O(#triangles). Throws InvalidArgument when there are no triangles.
[[nodiscard]] std::pair<MeshPoint, double> closestSurfacePoint(const Eigen::Ref<const MeshVertices>& vertices,
                                                               const std::vector<Triangle>& triangles,
                                                               const Eigen::Vector3d& query);

/// One control marker bound to the mesh.
struct MarkerBinding
{
  std::string label;
  MeshPoint point;
  double residual = 0.0;  ///< distance from the aligned neutral marker to `point`, take units (mm); NaN if unknown
};

/// Marker labels bound to mesh points, and the neutral-frame alignment that produced them.
struct MeshBinding
{
  std::vector<MarkerBinding> markers;
  Similarity alignment;        ///< take (neutral frame, head motion removed) → mesh
  bool hasAlignment = false;
  Eigen::Index meshVertices = 0;
};

/// Binding JSON: {"mesh_vertices": N, "alignment": {"scale", "rotation" (3 rows), "translation"},
/// "markers": {LABEL: VERTEX | {"vertex": V} | {"triangle": [a, b, c], "weights": [u, v, w]}, …}}
/// (per marker also "residual_mm"). O(#markers).
[[nodiscard]] std::string bindingJson(const MeshBinding& binding);

/// Parses binding JSON (`source` names it in errors) for a mesh of `vertexCount` vertices.
/// Throws FormatError for malformed JSON, a missing "markers" object, a vertex index outside the
/// mesh ("bound off the mesh"), weights that are negative, not finite or do not sum to 1, a label
/// given twice or a mesh_vertices count that differs. O(size).
[[nodiscard]] MeshBinding parseBinding(std::string_view text, const std::string& source, Eigen::Index vertexCount);
[[nodiscard]] MeshBinding readBinding(const std::filesystem::path& path, Eigen::Index vertexCount);
/// The binding JSON as a value inside another document (an actor profile embeds it). O(size).
void writeBinding(JsonWriter& json, const MeshBinding& binding);
/// parseBinding of a parsed value. O(size).
[[nodiscard]] MeshBinding bindingFromJson(const JsonValue& root, const std::string& source, Eigen::Index vertexCount);

struct AutoBindOptions
{
  /// User correspondences (marker row, vertex); ≥ 3 fix the similarity transform directly.
  std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs;
  /// Vertices markers may bind to (e.g. ICT FaceKit's face area 0…6705); empty: all. Faces with a
  /// vertex outside it are not used.
  std::vector<Eigen::Index> vertexSubset;
  int icpIterations = 40;
};

/// Binds each marker of a neutral frame (`neutral`, #markers × 3, head motion removed, take units)
/// to its nearest surface point after aligning the frame to the mesh with a similarity transform:
/// from the ≥ 3 user pairs when given (paired markers bind to their vertex), otherwise by
/// iterative closest point with a similarity update (Besl & McKay 1992 with Umeyama's step, the
/// scale kept within ±25 % of the start so the markers cannot shrink onto a small patch) started
/// from the principal axes and RMS radii of both point sets, in the 8 proper axis orientations,
/// keeping the start with the smallest RMS residual. Residuals are in take units.
/// Not a paper equation (the paper places its 38 points by hand, §3.1). Throws InvalidArgument for
/// fewer than 3 markers, a non-finite coordinate, a mesh without triangles in the subset, 1–2
/// pairs, or a pair out of range. O(8 · iterations · #markers · #subset + #markers · #triangles).
[[nodiscard]] MeshBinding autoBind(const Mesh& mesh, const std::vector<std::string>& labels,
                                   const Eigen::Ref<const PointSet>& neutral, const AutoBindOptions& options = {});

} // namespace mocap
