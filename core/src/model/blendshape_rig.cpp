#include "mocap/model/blendshape_rig.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace mocap {

namespace {

/// The entries of `shape` that `keep(vertex, delta row)` accepts, their vertices less `shift`.
template <typename Keep>
SparseShape filteredShape(const SparseShape& shape, Eigen::Index shift, Keep keep)
{
  SparseShape kept;
  kept.name = shape.name;
  std::vector<Eigen::Index> rows;
  for (Eigen::Index i = 0; i < shape.size(); ++i) {
    const Eigen::Index v = shape.vertices[static_cast<std::size_t>(i)];
    if (keep(v, shape.deltas.row(i))) {
      kept.vertices.push_back(v - shift);
      rows.push_back(i);
    }
  }
  kept.deltas = shape.deltas(rows, Eigen::all);
  return kept;
}

} // namespace

Eigen::Vector3d SparseShape::deltaOf(Eigen::Index vertex) const
{
  const auto it = std::lower_bound(vertices.begin(), vertices.end(), vertex);
  if (it == vertices.end() || *it != vertex)
    return Eigen::Vector3d::Zero();
  return deltas.row(it - vertices.begin()).transpose();
}

std::vector<std::string> BlendshapeRig::shapeNames() const
{
  std::vector<std::string> names;
  names.reserve(shapes.size());
  for (const SparseShape& shape : shapes)
    names.push_back(shape.name);
  return names;
}

std::optional<Eigen::Index> BlendshapeRig::shapeIndex(std::string_view name) const
{
  for (std::size_t s = 0; s < shapes.size(); ++s)
    if (shapes[s].name == name)
      return static_cast<Eigen::Index>(s);
  return std::nullopt;
}

void BlendshapeRig::evaluate(const Eigen::Ref<const Eigen::VectorXd>& weights, MeshVertices& out) const
{
  if (weights.size() != shapeCount())
    throw InvalidArgument("the rig has " + std::to_string(shapeCount()) + " shapes, not " +
                          std::to_string(weights.size()) + " weights");
  out = neutral.vertices;
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    const double w = weights(static_cast<Eigen::Index>(s));
    if (w == 0.0)
      continue;
    const SparseShape& shape = shapes[s];
    for (Eigen::Index i = 0; i < shape.size(); ++i)
      out.row(shape.vertices[static_cast<std::size_t>(i)]) += w * shape.deltas.row(i);
  }
}

SparseShape sparseShape(std::string name, const Eigen::Ref<const MeshVertices>& neutral,
                        const Eigen::Ref<const MeshVertices>& shape, double tolerance)
{
  if (shape.rows() != neutral.rows())
    throw InvalidArgument("shape '" + name + "' has " + std::to_string(shape.rows()) + " vertices, the neutral " +
                          std::to_string(neutral.rows()));
  if (!shape.allFinite())
    throw InvalidArgument("shape '" + name + "' has a non-finite coordinate");
  SparseShape sparse;
  sparse.name = std::move(name);
  std::vector<Eigen::Index> moved;
  for (Eigen::Index v = 0; v < shape.rows(); ++v)
    if ((shape.row(v) - neutral.row(v)).cwiseAbs().maxCoeff() > tolerance)
      moved.push_back(v);
  sparse.deltas.resize(static_cast<Eigen::Index>(moved.size()), 3);
  for (std::size_t i = 0; i < moved.size(); ++i)
    sparse.deltas.row(static_cast<Eigen::Index>(i)) = shape.row(moved[i]) - neutral.row(moved[i]);
  sparse.vertices = std::move(moved);
  return sparse;
}

void checkRig(const BlendshapeRig& rig)
{
  checkMesh(rig.neutral);
  if (rig.shapes.empty())
    throw InvalidArgument("the rig has no shapes");
  std::set<std::string> names;
  for (const SparseShape& shape : rig.shapes) {
    if (shape.name.empty())
      throw InvalidArgument("a rig shape has no name");
    if (!names.insert(shape.name).second)
      throw InvalidArgument("the rig has two shapes called '" + shape.name + "'");
    if (shape.deltas.rows() != shape.size())
      throw InvalidArgument("shape '" + shape.name + "' has " + std::to_string(shape.size()) + " vertices but " +
                            std::to_string(shape.deltas.rows()) + " deltas");
    if (!shape.deltas.allFinite())
      throw InvalidArgument("shape '" + shape.name + "' has a non-finite delta");
    for (std::size_t i = 0; i < shape.vertices.size(); ++i) {
      const Eigen::Index v = shape.vertices[i];
      if (v < 0 || v >= rig.neutral.vertexCount() || (i > 0 && v <= shape.vertices[i - 1]))
        throw InvalidArgument("shape '" + shape.name + "' has vertex " + std::to_string(v) +
                              " out of range or out of order");
    }
  }
}

BlendshapeRig selectShapes(const BlendshapeRig& rig, const std::vector<std::string>& names)
{
  BlendshapeRig selected;
  selected.neutral = rig.neutral;
  std::set<std::string> seen;
  for (const std::string& name : names) {
    if (!seen.insert(name).second)
      throw InvalidArgument("shape '" + name + "' is given twice");
    const std::optional<Eigen::Index> s = rig.shapeIndex(name);
    if (!s)
      throw InvalidArgument("the rig has no shape called '" + name + "'");
    selected.shapes.push_back(rig.shapes[static_cast<std::size_t>(*s)]);
  }
  return selected;
}

BlendshapeRig rigRegion(const BlendshapeRig& rig, Eigen::Index first, Eigen::Index last)
{
  if (first < 0 || last < first || last >= rig.neutral.vertexCount())
    throw InvalidArgument("vertex range " + std::to_string(first) + "…" + std::to_string(last) +
                          " is not inside the rig's vertices 0…" + std::to_string(rig.neutral.vertexCount() - 1));
  const auto inside = [&](Eigen::Index v) { return v >= first && v <= last; };
  BlendshapeRig region;
  region.neutral.vertices = rig.neutral.vertices.middleRows(first, last - first + 1);
  region.neutral.uvs = rig.neutral.uvs;
  region.neutral.normals = rig.neutral.normals;
  for (const MeshFace& face : rig.neutral.faces) {
    if (!std::all_of(face.vertices.begin(), face.vertices.end(), inside))
      continue;
    MeshFace kept = face;
    for (Eigen::Index& v : kept.vertices)
      v -= first;
    region.neutral.faces.push_back(std::move(kept));
  }
  if (region.neutral.faces.empty())
    throw InvalidArgument("no face lies wholly inside vertices " + std::to_string(first) + "…" + std::to_string(last));
  for (const SparseShape& shape : rig.shapes)
    region.shapes.push_back(filteredShape(shape, first, [&](Eigen::Index v, const auto&) { return inside(v); }));
  return region;
}

BlendshapeRig prunedRig(const BlendshapeRig& rig, double tolerance)
{
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
    throw InvalidArgument("the delta tolerance must be finite and not negative");
  BlendshapeRig pruned;
  pruned.neutral = rig.neutral;
  for (const SparseShape& shape : rig.shapes)
    pruned.shapes.push_back(
        filteredShape(shape, 0, [&](Eigen::Index, const auto& delta) { return delta.cwiseAbs().maxCoeff() > tolerance; }));
  return pruned;
}

} // namespace mocap
