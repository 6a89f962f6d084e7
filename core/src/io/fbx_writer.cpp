#include "mocap/io/fbx_writer.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/nearest_usable_frame.h"

#include <cmath>
#include <limits>

namespace mocap {

namespace {

/// A Model with its node attribute ("Null" or "LimbNode"); returns the model and its Properties70.
struct ModelObject
{
  std::int64_t id = 0;
  FbxNode* properties = nullptr;
};

ModelObject addModel(FbxDocument& fbx, std::string_view name, std::string_view subtype)
{
  const FbxDocument::Object model = fbx.addObject("Model", name, "Model", subtype);
  model.node->child("Version").addInt32(232);
  FbxNode& properties = model.node->child("Properties70");
  model.node->child("Shading").addBool(true);
  model.node->child("Culling").addString("CullingOff");
  if (subtype != "Mesh") {
    const bool bone = subtype == "LimbNode";
    const FbxDocument::Object attribute = fbx.addObject("NodeAttribute", name, "NodeAttribute", subtype);
    if (bone)
      addFbxProperty(attribute.node->child("Properties70"), "Size", "double", "Number", "").addDouble(1.0);
    attribute.node->child("TypeFlags").addString(bone ? "Skeleton" : "Null");
    fbx.connect(attribute.id, model.id);
  }
  return {model.id, &properties};
}

// ---- keys

/// A curve's frames as reduceKeys' times: uniform steps, so the frame index serves.
Eigen::VectorXd frameIndices(std::size_t frames)
{
  const auto n = static_cast<Eigen::Index>(frames);
  return Eigen::VectorXd::LinSpaced(n, 0.0, static_cast<double>(n - 1));
}

Eigen::VectorXd asDoubles(const std::vector<float>& curve)
{
  return Eigen::Map<const Eigen::VectorXf>(curve.data(), static_cast<Eigen::Index>(curve.size())).cast<double>();
}

/// The keys of each linear curve within `tolerance` of it (reduceKeys, each curve alone).
std::vector<KeyReduction> reduceEachCurve(const std::vector<std::vector<float>>& curves, double tolerance)
{
  std::vector<KeyReduction> reductions;
  for (const std::vector<float>& curve : curves)
    reductions.push_back(reduceFrameKeys(asDoubles(curve), tolerance));
  return reductions;
}

std::vector<std::vector<Eigen::Index>> keyFramesOf(const std::vector<KeyReduction>& reductions)
{
  std::vector<std::vector<Eigen::Index>> frames;
  for (const KeyReduction& r : reductions)
    frames.push_back(r.keys);
  return frames;
}

/// The largest 3-D distance of a marker's keyed X, Y and Z curves from its frames.
double largestDistance(const std::vector<std::vector<float>>& xyz, const std::vector<KeyReduction>& reductions)
{
  const std::size_t frames = xyz.front().size();
  Eigen::MatrixXd offset(static_cast<Eigen::Index>(frames), 3);
  for (std::size_t c = 0; c < 3; ++c) {
    const Eigen::VectorXd values = asDoubles(xyz[c]);
    offset.col(static_cast<Eigen::Index>(c)) =
        interpolateKeys(frameIndices(frames), values, reductions[c].keys) - values;
  }
  return frames == 0 ? 0.0 : offset.rowwise().norm().maxCoeff();
}

/// A constant curve's keys: its first frame, each change and its last frame.
std::vector<Eigen::Index> changeFrames(const std::vector<float>& curve)
{
  std::vector<Eigen::Index> frames;
  for (std::size_t f = 0; f < curve.size(); ++f)
    if (f == 0 || f + 1 == curve.size() || curve[f] != curve[f - 1])
      frames.push_back(static_cast<Eigen::Index>(f));
  return frames;
}

void checkTolerance(const FbxCurveKeys& keys)
{
  if (keys.tolerance && (!(*keys.tolerance >= 0.0) || !std::isfinite(*keys.tolerance)))
    throw InvalidArgument("FBX: the key tolerance must be finite and ≥ 0");
}

// ---- markers

/// One marker's null: translation keys every frame (held through gaps) and, when it has gaps, a
/// visibility curve. O(#frames).
void addMarker(FbxDocument& fbx, const Take& take, Eigen::Index marker, std::int64_t root, const FbxCurveKeys& keys)
{
  const ModelObject model = addModel(fbx, take.label(marker), "Null");
  fbx.connect(model.id, root);
  const std::vector<Eigen::Index> nearest = nearestUsableFrames(take, marker);
  const bool never = nearest.empty() || nearest.front() < 0;
  addFbxProperty(*model.properties, "Visibility", "Visibility", "", "A").addDouble(never ? 0.0 : 1.0);
  if (never)
    return;
  std::vector<std::vector<float>> xyz(3);
  std::vector<float> visible;
  bool gaps = false;
  for (std::size_t f = 0; f < nearest.size(); ++f) {
    const Eigen::Vector3d p = take.position(nearest[f], marker);
    for (int c = 0; c < 3; ++c)
      xyz[static_cast<std::size_t>(c)].push_back(static_cast<float>(p[c]));
    const bool here = nearest[f] == static_cast<Eigen::Index>(f);
    gaps = gaps || !here;
    visible.push_back(here ? 1.0F : 0.0F);
  }
  const Eigen::Vector3d first = take.position(nearest.front(), marker);
  addFbxProperty(*model.properties, "Lcl Translation", "Lcl Translation", "", "A")
      .addDouble(first.x())
      .addDouble(first.y())
      .addDouble(first.z());
  if (keys.tolerance) {
    // Each axis within tolerance / √3 keeps the marker within the tolerance in 3-D.
    const std::vector<KeyReduction> reductions = reduceEachCurve(xyz, *keys.tolerance / std::sqrt(3.0));
    const std::vector<std::vector<Eigen::Index>> frames = keyFramesOf(reductions);
    fbx.animate(model.id, "Lcl Translation", "T", {"d|X", "d|Y", "d|Z"}, xyz, FbxInterpolation::Linear, &frames);
    if (keys.counted) {
      Eigen::Index kept = 0;
      for (const KeyReduction& r : reductions)
        kept += static_cast<Eigen::Index>(r.keys.size());
      keys.counted->add(3 * static_cast<Eigen::Index>(nearest.size()), kept, largestDistance(xyz, reductions));
    }
  } else {
    fbx.animate(model.id, "Lcl Translation", "T", {"d|X", "d|Y", "d|Z"}, xyz, FbxInterpolation::Linear);
  }
  if (!gaps)
    return;
  const std::vector<std::vector<Eigen::Index>> visibleKeys{changeFrames(visible)};
  fbx.animate(model.id, "Visibility", "Visibility", {"d|Visibility"}, {visible}, FbxInterpolation::Constant,
              keys.tolerance ? &visibleKeys : nullptr);
}

// ---- rig

std::vector<double> flatten(const MeshVertices& points)
{
  return {points.data(), points.data() + points.size()};
}

/// The neutral as an FBX mesh: Vertices and PolygonVertexIndex (a polygon's last index stored as
/// −(index + 1)). O(#vertices + #corners).
FbxDocument::Object addMeshGeometry(FbxDocument& fbx, const Mesh& mesh)
{
  if (mesh.vertexCount() > std::numeric_limits<std::int32_t>::max())
    throw InvalidArgument("FBX: the mesh has more vertices than FBX indexes");
  const FbxDocument::Object geometry = fbx.addObject("Geometry", "Face", "Geometry", "Mesh");
  geometry.node->child("GeometryVersion").addInt32(124);
  geometry.node->child("Vertices").addDoubles(flatten(mesh.vertices));
  std::vector<std::int32_t> corners;
  for (const MeshFace& face : mesh.faces) {
    for (const Eigen::Index v : face.vertices)
      corners.push_back(static_cast<std::int32_t>(v));
    corners.back() = -corners.back() - 1;
  }
  geometry.node->child("PolygonVertexIndex").addInt32s(corners);
  return geometry;
}

const std::vector<double> kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

/// The skin that makes the mesh a skeletal mesh: every vertex bound with weight 1 to `bone`, the
/// bind pose identity. O(#vertices).
void addSkin(FbxDocument& fbx, std::int64_t geometry, std::int64_t mesh, std::int64_t bone, Eigen::Index vertices)
{
  const FbxDocument::Object skin = fbx.addObject("Deformer", "Face", "Deformer", "Skin");
  skin.node->child("Version").addInt32(101);
  skin.node->child("Link_DeformAcuracy").addDouble(50.0);
  const FbxDocument::Object cluster = fbx.addObject("Deformer", "root", "SubDeformer", "Cluster");
  cluster.node->child("Version").addInt32(100);
  cluster.node->child("UserData").addString("").addString("");
  std::vector<std::int32_t> indexes(static_cast<std::size_t>(vertices));
  for (std::size_t v = 0; v < indexes.size(); ++v)
    indexes[v] = static_cast<std::int32_t>(v);
  cluster.node->child("Indexes").addInt32s(indexes);
  cluster.node->child("Weights").addDoubles(std::vector<double>(indexes.size(), 1.0));
  cluster.node->child("Transform").addDoubles(kIdentity);
  cluster.node->child("TransformLink").addDoubles(kIdentity);
  fbx.connect(skin.id, geometry);
  fbx.connect(cluster.id, skin.id);
  fbx.connect(bone, cluster.id);

  const FbxDocument::Object pose = fbx.addObject("Pose", "Face", "Pose", "BindPose");
  pose.node->child("Type").addString("BindPose");
  pose.node->child("Version").addInt32(100);
  pose.node->child("NbPoseNodes").addInt32(2);
  for (const std::int64_t node : {mesh, bone}) {
    FbxNode& poseNode = pose.node->child("PoseNode");
    poseNode.child("Node").addInt64(node);
    poseNode.child("Matrix").addDoubles(kIdentity);
  }
}

/// One shape: its channel (animatable DeformPercent, full weight on every moved vertex) and its
/// sparse Shape geometry. Returns the channel's id. O(#moved vertices).
std::int64_t addShape(FbxDocument& fbx, const SparseShape& shape, std::int64_t blendShape)
{
  const FbxDocument::Object channel = fbx.addObject("Deformer", shape.name, "SubDeformer", "BlendShapeChannel");
  channel.node->child("Version").addInt32(100);
  channel.node->child("DeformPercent").addDouble(0.0);
  channel.node->child("FullWeights").addDoubles(std::vector<double>(shape.vertices.size(), 100.0));
  addFbxProperty(channel.node->child("Properties70"), "DeformPercent", "Number", "", "A").addDouble(0.0);
  const FbxDocument::Object geometry = fbx.addObject("Geometry", shape.name, "Geometry", "Shape");
  geometry.node->child("Version").addInt32(100);
  std::vector<std::int32_t> indexes;
  indexes.reserve(shape.vertices.size());
  for (const Eigen::Index v : shape.vertices)
    indexes.push_back(static_cast<std::int32_t>(v));
  geometry.node->child("Indexes").addInt32s(indexes);
  geometry.node->child("Vertices").addDoubles(flatten(shape.deltas));
  fbx.connect(geometry.id, channel.id);
  fbx.connect(channel.id, blendShape);
  return channel.id;
}

void checkWeights(const BlendshapeRig& rig, const Eigen::Ref<const Eigen::MatrixXd>& weights)
{
  if (weights.rows() > 0 && weights.cols() != rig.shapeCount())
    throw InvalidArgument("FBX: " + std::to_string(weights.cols()) + " weight columns for " +
                          std::to_string(rig.shapeCount()) + " shapes");
  if (!weights.allFinite())
    throw InvalidArgument("FBX: a weight is not finite");
}

/// Weight × 100 per frame: DeformPercent's scale. O(#frames).
std::vector<float> percentCurve(const Eigen::Ref<const Eigen::MatrixXd>& weights, Eigen::Index shape)
{
  std::vector<float> percent(static_cast<std::size_t>(weights.rows()));
  for (Eigen::Index f = 0; f < weights.rows(); ++f)
    percent[static_cast<std::size_t>(f)] = static_cast<float>(100.0 * weights(f, shape));
  return percent;
}

} // namespace

std::string markersFbx(const Take& take, FbxUpAxis up, const FbxCurveKeys& keys)
{
  checkTolerance(keys);
  if (const std::optional<Take> markers = withoutModelOutputs(take, "an FBX file"))
    return markersFbx(*markers, up, keys);
  FbxDocument fbx({up, take.units(), take.frameRate(), take.frameCount(), 0.0});
  const ModelObject root = addModel(fbx, "Markers", "Null");
  fbx.connect(root.id, 0);
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    addMarker(fbx, take, m, root.id, keys);
  return fbx.bytes();
}

void writeMarkersFbx(const std::filesystem::path& path, const Take& take, FbxUpAxis up, const FbxCurveKeys& keys)
{
  writeFileAtomically(path, markersFbx(take, up, keys));
}

std::string rigFbx(const BlendshapeRig& rig, const Eigen::Ref<const Eigen::MatrixXd>& weights, double frameRate,
                   const FbxRigOptions& options)
{
  checkRig(rig);
  checkWeights(rig, weights);
  checkTolerance(options.keys);
  FbxDocument fbx({options.up, options.unit, frameRate, weights.rows(), options.startSeconds});
  const ModelObject mesh = addModel(fbx, "Face", "Mesh");
  const ModelObject bone = addModel(fbx, "root", "LimbNode");
  fbx.connect(mesh.id, 0);
  fbx.connect(bone.id, 0);
  const FbxDocument::Object geometry = addMeshGeometry(fbx, rig.neutral);
  fbx.connect(geometry.id, mesh.id);
  addSkin(fbx, geometry.id, mesh.id, bone.id, rig.neutral.vertexCount());

  const FbxDocument::Object blendShape = fbx.addObject("Deformer", "Face", "Deformer", "BlendShape");
  blendShape.node->child("Version").addInt32(100);
  fbx.connect(blendShape.id, geometry.id);
  for (Eigen::Index s = 0; s < rig.shapeCount(); ++s) {
    const std::int64_t channel = addShape(fbx, rig.shapes[static_cast<std::size_t>(s)], blendShape.id);
    if (weights.rows() == 0)
      continue;
    const std::vector<std::vector<float>> percent{percentCurve(weights, s)};
    if (!options.keys.tolerance) {
      fbx.animate(channel, "DeformPercent", "DeformPercent", {"d|DeformPercent"}, percent, FbxInterpolation::Linear);
      continue;
    }
    const std::vector<KeyReduction> reduced = reduceEachCurve(percent, 100.0 * *options.keys.tolerance);  // × 100
    const std::vector<std::vector<Eigen::Index>> frames = keyFramesOf(reduced);
    fbx.animate(channel, "DeformPercent", "DeformPercent", {"d|DeformPercent"}, percent, FbxInterpolation::Linear,
                &frames);
    if (options.keys.counted)
      options.keys.counted->add(weights.rows(), static_cast<Eigen::Index>(frames.front().size()),
                                reduced.front().maxError / 100.0);
  }
  return fbx.bytes();
}

void writeRigFbx(const std::filesystem::path& path, const BlendshapeRig& rig,
                 const Eigen::Ref<const Eigen::MatrixXd>& weights, double frameRate, const FbxRigOptions& options)
{
  writeFileAtomically(path, rigFbx(rig, weights, frameRate, options));
}

} // namespace mocap
