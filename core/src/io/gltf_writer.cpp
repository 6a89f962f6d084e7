#include "mocap/io/gltf_writer.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <sstream>

namespace mocap {

namespace {

/// Appends `bytes` to the one buffer as a new view (4-byte aligned, as accessors need) and
/// returns the view's index.
int addView(tinygltf::Model& model, const void* bytes, std::size_t size, int target = 0)
{
  std::vector<unsigned char>& data = model.buffers[0].data;
  data.resize((data.size() + 3) / 4 * 4);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = size;
  view.target = target;
  const auto* begin = static_cast<const unsigned char*>(bytes);
  data.insert(data.end(), begin, begin + size);
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size()) - 1;
}

int addAccessor(tinygltf::Model& model, tinygltf::Accessor accessor)
{
  model.accessors.push_back(std::move(accessor));
  return static_cast<int>(model.accessors.size()) - 1;
}

/// A VEC3 float accessor over `points` (#points × 3), with the min/max glTF requires of positions.
tinygltf::Accessor vec3Accessor(const std::vector<float>& points)
{
  tinygltf::Accessor a;
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.type = TINYGLTF_TYPE_VEC3;
  a.count = points.size() / 3;
  a.minValues.assign(3, 0.0);
  a.maxValues.assign(3, 0.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t c = i % 3;
    const auto value = static_cast<double>(points[i]);
    if (i < 3 || value < a.minValues[c])
      a.minValues[c] = value;
    if (i < 3 || value > a.maxValues[c])
      a.maxValues[c] = value;
  }
  return a;
}

int addPositions(tinygltf::Model& model, const BlendshapeRig& rig)
{
  std::vector<float> positions;
  for (Eigen::Index v = 0; v < rig.neutral.vertexCount(); ++v)
    for (int c = 0; c < 3; ++c)
      positions.push_back(static_cast<float>(rig.neutral.vertices(v, c)));
  tinygltf::Accessor a = vec3Accessor(positions);
  a.bufferView = addView(model, positions.data(), positions.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
  return addAccessor(model, a);
}

int addIndices(tinygltf::Model& model, const BlendshapeRig& rig)
{
  std::vector<std::uint32_t> indices;
  for (const Triangle& t : rig.neutral.triangles())
    for (const Eigen::Index v : t)
      indices.push_back(static_cast<std::uint32_t>(v));
  tinygltf::Accessor a;
  a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  a.type = TINYGLTF_TYPE_SCALAR;
  a.count = indices.size();
  a.bufferView =
      addView(model, indices.data(), indices.size() * sizeof(std::uint32_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  return addAccessor(model, a);
}

/// A morph target as a sparse accessor: zeros except at the moved vertices. A shape that moves
/// nothing is an accessor without data, which glTF reads as all zeros.
int addMorphTarget(tinygltf::Model& model, const SparseShape& shape, std::size_t vertexCount)
{
  std::vector<float> deltas;
  std::vector<std::uint32_t> indices;
  for (Eigen::Index i = 0; i < shape.size(); ++i) {
    indices.push_back(static_cast<std::uint32_t>(shape.vertices[static_cast<std::size_t>(i)]));
    for (int c = 0; c < 3; ++c)
      deltas.push_back(static_cast<float>(shape.deltas(i, c)));
  }
  tinygltf::Accessor a = vec3Accessor(deltas);
  a.count = vertexCount;
  a.bufferView = -1;
  // The unmoved vertices' zero deltas belong to the range too.
  for (int c = 0; c < 3; ++c) {
    a.minValues[static_cast<std::size_t>(c)] = std::min(a.minValues[static_cast<std::size_t>(c)], 0.0);
    a.maxValues[static_cast<std::size_t>(c)] = std::max(a.maxValues[static_cast<std::size_t>(c)], 0.0);
  }
  if (!indices.empty()) {
    a.sparse.isSparse = true;
    a.sparse.count = static_cast<int>(indices.size());
    a.sparse.indices.bufferView = addView(model, indices.data(), indices.size() * sizeof(std::uint32_t));
    a.sparse.indices.byteOffset = 0;
    a.sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.sparse.values.bufferView = addView(model, deltas.data(), deltas.size() * sizeof(float));
    a.sparse.values.byteOffset = 0;
  }
  return addAccessor(model, a);
}

void addAnimation(tinygltf::Model& model, const Eigen::Ref<const Eigen::MatrixXd>& weights, double frameRate,
                  const std::vector<Eigen::Index>& keys, std::optional<double> startSeconds)
{
  std::vector<float> times, values;
  const auto keyCount = keys.empty() ? weights.rows() : static_cast<Eigen::Index>(keys.size());
  for (Eigen::Index k = 0; k < keyCount; ++k) {
    const Eigen::Index f = keys.empty() ? k : keys[static_cast<std::size_t>(k)];
    times.push_back(static_cast<float>(static_cast<double>(f) / frameRate));
    for (Eigen::Index s = 0; s < weights.cols(); ++s)
      values.push_back(static_cast<float>(weights(f, s)));
  }
  tinygltf::Accessor input;
  input.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  input.type = TINYGLTF_TYPE_SCALAR;
  input.count = times.size();
  input.minValues = {static_cast<double>(times.front())};
  input.maxValues = {static_cast<double>(times.back())};
  input.bufferView = addView(model, times.data(), times.size() * sizeof(float));
  tinygltf::Accessor output;
  output.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  output.type = TINYGLTF_TYPE_SCALAR;
  output.count = values.size();
  output.bufferView = addView(model, values.data(), values.size() * sizeof(float));
  tinygltf::AnimationSampler sampler;
  sampler.input = addAccessor(model, input);
  sampler.output = addAccessor(model, output);
  sampler.interpolation = "LINEAR";
  tinygltf::AnimationChannel channel;
  channel.sampler = 0;
  channel.target_node = 0;
  channel.target_path = "weights";
  tinygltf::Animation animation;
  animation.name = "solve";
  if (startSeconds)
    animation.extras = tinygltf::Value(tinygltf::Value::Object{{"startSeconds", tinygltf::Value(*startSeconds)}});
  animation.samplers.push_back(sampler);
  animation.channels.push_back(channel);
  model.animations.push_back(animation);
}

} // namespace

std::string rigGlb(const BlendshapeRig& rig, const Eigen::Ref<const Eigen::MatrixXd>& weights, double frameRate,
                   const std::vector<Eigen::Index>& keys, std::optional<double> startSeconds)
{
  checkRig(rig);
  if (weights.rows() > 0 && weights.cols() != rig.shapeCount())
    throw InvalidArgument("glTF: " + std::to_string(weights.cols()) + " weight columns for " +
                          std::to_string(rig.shapeCount()) + " shapes");
  if (!weights.allFinite())
    throw InvalidArgument("glTF: a weight is not finite");
  if (!(frameRate > 0.0) || !std::isfinite(frameRate))
    throw InvalidArgument("glTF: the frame rate must be positive");
  if (startSeconds && !(*startSeconds >= 0.0 && std::isfinite(*startSeconds)))
    throw InvalidArgument("glTF: the start time must be finite and ≥ 0 seconds");
  if (!keys.empty() && (keys.front() != 0 || keys.back() != weights.rows() - 1 ||
                        std::adjacent_find(keys.begin(), keys.end(), std::greater_equal<>()) != keys.end()))
    throw InvalidArgument("glTF: the key frames must ascend from the first frame to the last");
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "Mocap Studio";
  model.buffers.emplace_back();
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] = addPositions(model, rig);
  primitive.indices = addIndices(model, rig);
  tinygltf::Mesh mesh;
  mesh.name = "rig";
  std::vector<tinygltf::Value> names;
  for (const SparseShape& shape : rig.shapes) {
    primitive.targets.push_back(
        {{"POSITION", addMorphTarget(model, shape, static_cast<std::size_t>(rig.neutral.vertexCount()))}});
    names.emplace_back(shape.name);
    mesh.weights.push_back(0.0);
  }
  mesh.primitives.push_back(primitive);
  mesh.extras = tinygltf::Value(tinygltf::Value::Object{{"targetNames", tinygltf::Value(names)}});
  model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.name = "rig";
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  if (weights.rows() > 0)
    addAnimation(model, weights, frameRate, keys, startSeconds);

  std::ostringstream out;
  if (!tinygltf::TinyGLTF().WriteGltfSceneToStream(&model, out, false, true))
    throw IoError("glTF: the GLB could not be serialised");
  return out.str();
}

void writeRigGlb(const std::filesystem::path& path, const BlendshapeRig& rig,
                 const Eigen::Ref<const Eigen::MatrixXd>& weights, double frameRate,
                 const std::vector<Eigen::Index>& keys, std::optional<double> startSeconds)
{
  writeFileAtomically(path, rigGlb(rig, weights, frameRate, keys, startSeconds));
}

} // namespace mocap
