#include "mocap/deform/mesh_binding.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_reader.h"
#include "mocap/base/json_writer.h"
#include "mocap/base/number_text.h"
#include "mocap/math/registration.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace mocap {

Eigen::Vector3d MeshPoint::on(const Eigen::Ref<const MeshVertices>& positions) const
{
  return weights(0) * positions.row(vertices[0]).transpose() + weights(1) * positions.row(vertices[1]).transpose() +
         weights(2) * positions.row(vertices[2]).transpose();
}

Eigen::Vector3d closestTriangleWeights(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       const Eigen::Vector3d& c)
{
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0)
    return {1.0, 0.0, 0.0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3)
    return {0.0, 1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 - d3 > 0.0 ? d1 / (d1 - d3) : 0.0;
    return {1.0 - v, v, 0.0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6)
    return {0.0, 0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 - d6 > 0.0 ? d2 / (d2 - d6) : 0.0;
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double denominator = (d4 - d3) + (d5 - d6);
    const double w = denominator > 0.0 ? (d4 - d3) / denominator : 0.0;
    return {0.0, 1.0 - w, w};
  }
  const double total = va + vb + vc;
  if (!(total > 0.0))  // degenerate: the regions above did not catch it; take vertex a
    return {1.0, 0.0, 0.0};
  const double v = vb / total, w = vc / total;
  return {1.0 - v - w, v, w};
}

std::pair<MeshPoint, double> closestSurfacePoint(const Eigen::Ref<const MeshVertices>& vertices,
                                                 const std::vector<Triangle>& triangles, const Eigen::Vector3d& query)
{
  if (triangles.empty())
    throw InvalidArgument("closest surface point: the mesh has no triangles");
  MeshPoint best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (const Triangle& t : triangles) {
    const Eigen::Vector3d a = vertices.row(t[0]).transpose();
    const Eigen::Vector3d b = vertices.row(t[1]).transpose();
    const Eigen::Vector3d c = vertices.row(t[2]).transpose();
    // Cheap reject: the point is farther from the triangle's bounding sphere than the best so far.
    const Eigen::Vector3d centre = (a + b + c) / 3.0;
    const double radius = std::sqrt(std::max({(a - centre).squaredNorm(), (b - centre).squaredNorm(),
                                              (c - centre).squaredNorm()}));
    if ((query - centre).norm() - radius > bestDistance)
      continue;
    const Eigen::Vector3d w = closestTriangleWeights(query, a, b, c);
    const double distance = (w(0) * a + w(1) * b + w(2) * c - query).norm();
    if (distance < bestDistance) {
      bestDistance = distance;
      best = MeshPoint{t, w};
    }
  }
  // Snap to a vertex representation when the point is one, so bindings read as vertex indices.
  for (int k = 0; k < 3; ++k)
    if (best.weights(k) == 1.0)
      best = MeshPoint::atVertex(best.vertices[static_cast<std::size_t>(k)]);
  return {best, bestDistance};
}

// ---------------------------------------------------------------------------------------- JSON

std::string bindingJson(const MeshBinding& binding)
{
  JsonWriter json;
  writeBinding(json, binding);
  return json.str() + "\n";
}

void writeBinding(JsonWriter& json, const MeshBinding& binding)
{
  json.beginObject();
  json.key("mesh_vertices").value(static_cast<std::int64_t>(binding.meshVertices));
  if (binding.hasAlignment) {
    json.key("alignment").beginObject();
    json.key("scale").value(binding.alignment.scale);
    json.key("rotation").beginArray();
    for (int r = 0; r < 3; ++r) {
      json.beginArray();
      for (int c = 0; c < 3; ++c)
        json.value(binding.alignment.rotation(r, c));
      json.endArray();
    }
    json.endArray();
    json.key("translation").beginArray();
    for (int c = 0; c < 3; ++c)
      json.value(binding.alignment.translation(c));
    json.endArray();
    json.endObject();
  }
  json.key("markers").beginObject();
  for (const MarkerBinding& marker : binding.markers) {
    json.key(marker.label).beginObject();
    if (marker.point.isVertex()) {
      json.key("vertex").value(static_cast<std::int64_t>(marker.point.vertices[0]));
    } else {
      json.key("triangle").beginArray();
      for (const Eigen::Index v : marker.point.vertices)
        json.value(static_cast<std::int64_t>(v));
      json.endArray();
      json.key("weights").beginArray();
      for (int k = 0; k < 3; ++k)
        json.value(marker.point.weights(k));
      json.endArray();
    }
    json.key("residual_mm").value(marker.residual);
    json.endObject();
  }
  json.endObject();
  json.endObject();
}

namespace {

double numberOf(const JsonValue* value, const std::string& source, const std::string& what)
{
  if (!value || !value->isNumber())
    throw FormatError(source, what + " must be a number");
  return value->number(what);
}

Eigen::Index vertexOf(const JsonValue* value, const std::string& source, const std::string& label,
                      Eigen::Index vertexCount)
{
  const double v = numberOf(value, source, "marker " + label + ": vertex");
  if (v != std::floor(v) || v < 0.0 || v >= static_cast<double>(vertexCount))
    throw FormatError(source, "marker " + label + " is bound off the mesh: vertex " + std::to_string(v) +
                                  " is not one of its " + std::to_string(vertexCount) + " vertices");
  return static_cast<Eigen::Index>(v);
}

MeshPoint pointOf(const JsonValue& value, const std::string& source, const std::string& label,
                  Eigen::Index vertexCount)
{
  if (value.isNumber())
    return MeshPoint::atVertex(vertexOf(&value, source, label, vertexCount));
  if (!value.isObject())
    throw FormatError(source, "marker " + label + ": expected a vertex index or an object");
  const std::string what = "marker " + label;
  if (const JsonValue* vertex = value.find("vertex", what))
    return MeshPoint::atVertex(vertexOf(vertex, source, label, vertexCount));
  const JsonValue* triangle = value.find("triangle", what);
  const JsonValue* weights = value.find("weights", what);
  if (!triangle || !weights || !triangle->isArray() || !weights->isArray() || triangle->array(what).size() != 3 ||
      weights->array(what).size() != 3)
    throw FormatError(source, what + ": needs \"vertex\" or \"triangle\" and \"weights\" of 3 entries");
  MeshPoint point;
  for (std::size_t k = 0; k < 3; ++k) {
    point.vertices[k] = vertexOf(&triangle->array(what)[k], source, label, vertexCount);
    point.weights(static_cast<Eigen::Index>(k)) = numberOf(&weights->array(what)[k], source, what + ": weight");
  }
  if ((point.weights.array() < -1e-9).any() || std::abs(point.weights.sum() - 1.0) > 1e-6)
    throw FormatError(source, "marker " + label +
                                  " is bound off the mesh: barycentric weights must be ≥ 0 and sum to 1");
  return point;
}

} // namespace

MeshBinding parseBinding(std::string_view text, const std::string& source, Eigen::Index vertexCount)
{
  return bindingFromJson(parseJson(text, source), source, vertexCount);
}

MeshBinding bindingFromJson(const JsonValue& root, const std::string& source, Eigen::Index vertexCount)
{
  if (!root.isObject())
    throw FormatError(source, "a binding is a JSON object");
  const JsonValue* markers = root.find("markers", "the binding");
  if (!markers || !markers->isObject())
    throw FormatError(source, "a binding needs a \"markers\" object (label → vertex)");
  MeshBinding binding;
  binding.meshVertices = vertexCount;
  if (const JsonValue* count = root.find("mesh_vertices", "the binding"))
    if (const double made = numberOf(count, source, "mesh_vertices"); made != static_cast<double>(vertexCount)) {
      std::string madeText;  // any number (a cast of 1e26 to an integer would be undefined)
      appendNumber(madeText, made);
      throw FormatError(source, "made for a mesh of " + madeText + " vertices, this one has " + std::to_string(vertexCount));
    }
  // A label given twice keeps its last binding (JSON objects keep the last of repeated keys).
  for (const auto& [label, value] : markers->object("markers")) {
    MarkerBinding marker{label, pointOf(value, source, label, vertexCount), std::nan("")};
    if (value.isObject())
      if (const JsonValue* residual = value.find("residual_mm", label); residual && residual->isNumber())
        marker.residual = residual->number("residual_mm");
    binding.markers.push_back(marker);
  }
  if (binding.markers.empty())
    throw FormatError(source, "the binding has no markers");
  if (const JsonValue* alignment = root.find("alignment", "the binding")) {
    const std::string what = "the alignment";
    if (!alignment->isObject())
      throw FormatError(source, "alignment needs a 3×3 rotation and a translation of 3");
    const JsonValue* rotation = alignment->find("rotation", what);
    const JsonValue* translation = alignment->find("translation", what);
    binding.alignment.scale = numberOf(alignment->find("scale", what), source, "alignment scale");
    if (!rotation || !rotation->isArray() || rotation->array(what).size() != 3 || !translation ||
        !translation->isArray() || translation->array(what).size() != 3)
      throw FormatError(source, "alignment needs a 3×3 rotation and a translation of 3");
    for (std::size_t r = 0; r < 3; ++r) {
      const JsonValue& row = rotation->array(what)[r];
      if (!row.isArray() || row.array(what).size() != 3)
        throw FormatError(source, "alignment rotation must have 3 rows of 3");
      for (std::size_t c = 0; c < 3; ++c)
        binding.alignment.rotation(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) =
            numberOf(&row.array(what)[c], source, "rotation entry");
      binding.alignment.translation(static_cast<Eigen::Index>(r)) =
          numberOf(&translation->array(what)[r], source, "translation entry");
    }
    binding.hasAlignment = true;
  }
  return binding;
}

MeshBinding readBinding(const std::filesystem::path& path, Eigen::Index vertexCount)
{
  return parseBinding(readFileBytes(path), path.string(), vertexCount);
}

// ----------------------------------------------------------------------------------- auto-binder

MeshBinding autoBind(const Mesh& mesh, const std::vector<std::string>& labels, const Eigen::Ref<const PointSet>& neutral,
                     const AutoBindOptions& options)
{
  if (neutral.rows() < 3 || static_cast<std::size_t>(neutral.rows()) != labels.size())
    throw InvalidArgument("bind: needs at least 3 markers with one label each");
  if (!neutral.allFinite())
    throw InvalidArgument("bind: a neutral marker position is not finite");
  std::vector<bool> allowed(static_cast<std::size_t>(mesh.vertexCount()), options.vertexSubset.empty());
  for (const Eigen::Index v : options.vertexSubset) {
    if (v < 0 || v >= mesh.vertexCount())
      throw InvalidArgument("bind: vertex " + std::to_string(v) + " is not in the mesh");
    allowed[static_cast<std::size_t>(v)] = true;
  }
  std::vector<Triangle> triangles;
  for (const Triangle& t : mesh.triangles())
    if (allowed[static_cast<std::size_t>(t[0])] && allowed[static_cast<std::size_t>(t[1])] &&
        allowed[static_cast<std::size_t>(t[2])])
      triangles.push_back(t);
  if (triangles.empty())
    throw InvalidArgument("bind: the mesh has no triangles to bind to");
  std::vector<Eigen::Index> used;
  for (Eigen::Index v = 0; v < mesh.vertexCount(); ++v)
    if (allowed[static_cast<std::size_t>(v)])
      used.push_back(v);
  PointSet candidates(static_cast<Eigen::Index>(used.size()), 3);
  for (std::size_t i = 0; i < used.size(); ++i)
    candidates.row(static_cast<Eigen::Index>(i)) = mesh.vertices.row(used[i]);

  MeshBinding binding;
  binding.meshVertices = mesh.vertexCount();
  binding.hasAlignment = true;
  if (!options.pairs.empty()) {
    if (options.pairs.size() < 3)
      throw InvalidArgument("bind: --pairs needs at least 3 correspondences, got " + std::to_string(options.pairs.size()));
    PointSet from(static_cast<Eigen::Index>(options.pairs.size()), 3), to(from.rows(), 3);
    for (std::size_t i = 0; i < options.pairs.size(); ++i) {
      const auto [marker, vertex] = options.pairs[i];
      if (marker < 0 || marker >= neutral.rows() || vertex < 0 || vertex >= mesh.vertexCount())
        throw InvalidArgument("bind: pair " + std::to_string(i + 1) + " is out of range");
      from.row(static_cast<Eigen::Index>(i)) = neutral.row(marker);
      to.row(static_cast<Eigen::Index>(i)) = mesh.vertices.row(vertex);
    }
    binding.alignment = fitSimilarity(from, to);
  } else {
    // Starts: the 8 right-handed sign choices of matching principal axes (two orders of the two
    // largest), each also turned ±20° about every axis, since the markers cover only part of the
    // mesh and their axes match the mesh's only roughly. Every start runs a cheap ICP to the
    // nearest vertex; the best few are refined against the surface.
    const PrincipalFrame source = principalFrame(neutral);
    const PrincipalFrame target = principalFrame(candidates);
    IcpOptions toVertex;  // each marker pulls its closest vertex
    toVertex.maxIterations = options.icpIterations;
    toVertex.errorTolerance = 1e-9;
    IcpOptions toSurface = toVertex;  // each marker pulls its closest surface point
    toSurface.closest = [&](const Eigen::Vector3d& p) -> Eigen::Vector3d {
      return closestSurfacePoint(mesh.vertices, triangles, p).first.on(mesh.vertices);
    };
    // Nearest-point pairing rewards shrinking the markers onto a small patch; keep the scale
    // within ±25 % of the start (the RMS-radius ratio of both sets).
    const auto keepScaleNear = [](IcpOptions o, const Similarity& start) {
      o.minScale = 0.8 * start.scale;
      o.maxScale = 1.25 * start.scale;
      return o;
    };
    std::vector<IcpResult> coarse;
    for (int order = 0; order < 2; ++order)
      for (int signs = 0; signs < 4; ++signs)
        for (int turn = 0; turn < 7; ++turn) {
          Eigen::Matrix3d axes = target.axes;
          if (order == 1)
            axes.col(0).swap(axes.col(1));
          axes.col(0) *= (signs & 1) ? -1.0 : 1.0;
          axes.col(1) *= (signs & 2) ? -1.0 : 1.0;
          axes.col(2) = axes.col(0).cross(axes.col(1));
          const double angle = turn == 0 ? 0.0 : (turn % 2 ? 0.35 : -0.35);
          const Eigen::Matrix3d tilt =
              Eigen::AngleAxisd(angle, target.axes.col(turn == 0 ? 0 : (turn - 1) / 2)).toRotationMatrix();
          const Similarity start =
              similarityThrough(tilt * axes * source.axes.transpose(),
                                source.radius > 0.0 ? target.radius / source.radius : 1.0, source.centre, target.centre);
          coarse.push_back(icp(neutral, candidates, start, keepScaleNear(toVertex, start)));
        }
    const auto byRms = [](const IcpResult& a, const IcpResult& b) { return a.rms < b.rms; };
    std::sort(coarse.begin(), coarse.end(), byRms);
    IcpResult best;
    for (std::size_t i = 0; i < std::min<std::size_t>(4, coarse.size()); ++i) {
      // Each refinement keeps its scale within ±25 % of its own start.
      const IcpResult refined = icp(neutral, candidates, coarse[i].transform, keepScaleNear(toSurface, coarse[i].transform));
      if (refined.rms < best.rms)
        best = refined;
    }
    binding.alignment = best.transform;
  }
  for (Eigen::Index m = 0; m < neutral.rows(); ++m) {
    const auto pair = std::find_if(options.pairs.begin(), options.pairs.end(),
                                   [&](const auto& p) { return p.first == m; });
    const Eigen::Vector3d aligned = binding.alignment.apply(Eigen::Vector3d(neutral.row(m).transpose()));
    MarkerBinding marker;
    marker.label = labels[static_cast<std::size_t>(m)];
    if (pair != options.pairs.end()) {
      marker.point = MeshPoint::atVertex(pair->second);
      marker.residual = (mesh.vertices.row(pair->second).transpose() - aligned).norm() / binding.alignment.scale;
    } else {
      const auto [point, distance] = closestSurfacePoint(mesh.vertices, triangles, aligned);
      marker.point = point;
      marker.residual = distance / binding.alignment.scale;
    }
    binding.markers.push_back(marker);
  }
  return binding;
}

} // namespace mocap
