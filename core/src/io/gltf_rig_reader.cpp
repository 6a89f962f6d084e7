#include "mocap/io/gltf_rig_reader.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <optional>

namespace mocap {

namespace {

constexpr std::uint32_t kGlbJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::size_t kGlbHeader = 12, kChunkHeader = 8;

std::uint32_t littleEndian32(std::string_view bytes, std::size_t at)
{
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i)
    value |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  return value;
}

bool isGlb(std::string_view bytes)
{
  return bytes.substr(0, 4) == "glTF";
}

/// Checks the GLB header and chunk lengths against the bytes (TinyGLTF 2.7 lets a BIN chunk run
/// 8 bytes past the end) and returns the length the header gives.
std::size_t checkGlbContainer(std::string_view bytes, const std::string& source)
{
  if (bytes.size() < kGlbHeader + kChunkHeader)
    throw FormatError(source, "truncated GLB: " + std::to_string(bytes.size()) + " bytes, less than its headers");
  if (const std::uint32_t version = littleEndian32(bytes, 4); version != 2)
    throw FormatError(source, 4, "GLB version " + std::to_string(version) + " (expected 2)");
  const std::uint64_t length = littleEndian32(bytes, 8);
  if (length > bytes.size())
    throw FormatError(source, 8,
                      "truncated GLB: the header gives " + std::to_string(length) + " bytes, the file has " +
                          std::to_string(bytes.size()));
  if (littleEndian32(bytes, 16) != kGlbJsonChunk)
    throw FormatError(source, 16, "the first GLB chunk is not JSON");
  const std::uint64_t jsonEnd = kGlbHeader + kChunkHeader + std::uint64_t{littleEndian32(bytes, 12)};
  if (jsonEnd > length)
    throw FormatError(source, 12, "the GLB's JSON chunk runs past its end");
  if (jsonEnd < length) {
    if (jsonEnd + kChunkHeader > length)
      throw FormatError(source, jsonEnd, "truncated GLB chunk header");
    if (jsonEnd + kChunkHeader + littleEndian32(bytes, static_cast<std::size_t>(jsonEnd)) > length)
      throw FormatError(source, jsonEnd, "the GLB's second chunk runs past its end");
  }
  return static_cast<std::size_t>(length);
}

// Images are not part of a rig: they are skipped, not decoded.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*)
{
  return true;
}

// File callbacks that read nothing, for bytes parsed without a folder to resolve URIs in.
bool noFileExists(const std::string&, void*)
{
  return false;
}
std::string samePath(const std::string& path, void*)
{
  return path;
}
bool noFileRead(std::vector<unsigned char>*, std::string*, const std::string&, void*)
{
  return false;
}
bool noFileWrite(std::string*, const std::string&, const std::vector<unsigned char>&, void*)
{
  return false;
}

std::string trimmed(std::string text)
{
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    text.pop_back();
  return text.empty() ? "unknown error" : text;
}

tinygltf::Model loadModel(std::string_view bytes, const std::string& source, const std::filesystem::path& baseDir)
{
  if (bytes.size() > std::numeric_limits<unsigned int>::max())
    throw FormatError(source, "larger than 4 GiB, more than a glTF loader reads");
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&skipImage, nullptr);
  if (baseDir.empty())
    loader.SetFsCallbacks({&noFileExists, &samePath, &noFileRead, &noFileWrite, nullptr});
  tinygltf::Model model;
  std::string error, warning;
  bool loaded = false;
  try {
    if (isGlb(bytes)) {
      const std::size_t length = checkGlbContainer(bytes, source);
      loaded = loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                           static_cast<unsigned int>(length), baseDir.string());
    } else {
      loaded = loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), static_cast<unsigned int>(bytes.size()),
                                          baseDir.string());
    }
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!loaded)
    throw FormatError(source, "not a readable glTF 2.0 file: " + trimmed(error));
  return model;
}

/// Extensions that change how geometry is stored; a file that requires one cannot be read here.
void refuseGeometryExtensions(const tinygltf::Model& model, const std::string& source)
{
  for (const char* name : {"KHR_mesh_quantization", "KHR_draco_mesh_compression", "EXT_meshopt_compression"})
    if (std::find(model.extensionsRequired.begin(), model.extensionsRequired.end(), name) !=
        model.extensionsRequired.end())
      throw FormatError(source, std::string("requires ") + name + ", which is not read (export positions as float)");
}

/// The bytes of accessor data a rig may read. A real rig reads each byte of its buffers about once;
/// primitives or morph targets that all name one accessor would expand a small file into
/// gigabytes, so reads stop at kReadFactor times what the buffers hold (plus a little for tiny files).
class ReadBudget
{
public:
  static constexpr std::uint64_t kReadFactor = 16, kAllowance = 64 * 1024;

  explicit ReadBudget(const tinygltf::Model& model)
  {
    for (const tinygltf::Buffer& buffer : model.buffers)
      m_held += buffer.data.size();
    m_limit = kReadFactor * m_held + kAllowance;
  }

  /// Counts `bytes` more; false, counting nothing, when they would pass the limit.
  bool take(std::uint64_t bytes)
  {
    if (bytes > m_limit - m_read)
      return false;
    m_read += bytes;
    return true;
  }

  [[nodiscard]] std::uint64_t held() const { return m_held; }
  [[nodiscard]] std::uint64_t limit() const { return m_limit; }

private:
  std::uint64_t m_held = 0, m_limit = 0, m_read = 0;
};

/// The model being read, the name errors give and what is left to read.
struct Source
{
  const tinygltf::Model& model;
  const std::string& name;
  ReadBudget& budget;
};

[[noreturn]] void fail(const Source& s, const std::string& message)
{
  throw FormatError(s.name, message);
}

/// Counts `bytes` of accessor data about to be read, before anything is allocated for them.
void chargeRead(const Source& s, std::uint64_t bytes, const std::string& what)
{
  if (!s.budget.take(bytes))
    fail(s, what + ": the rig would read more than " + std::to_string(s.budget.limit()) +
                " bytes of accessor data from buffers of " + std::to_string(s.budget.held()) +
                " bytes; its primitives or morph targets reuse accessors too often");
}

std::size_t componentBytes(int componentType)
{
  switch (componentType) {
  case TINYGLTF_COMPONENT_TYPE_BYTE:
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
    return 1;
  case TINYGLTF_COMPONENT_TYPE_SHORT:
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
    return 2;
  case TINYGLTF_COMPONENT_TYPE_INT:
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
  case TINYGLTF_COMPONENT_TYPE_FLOAT:
    return 4;
  default:
    return 0;  // DOUBLE is not a glTF 2.0 component type
  }
}

template <typename T>
double loadAs(const unsigned char* at)
{
  T value;
  std::memcpy(&value, at, sizeof(T));
  return static_cast<double>(value);
}

/// One component at `at` (glTF is little-endian, as every host we build for).
double componentValue(const unsigned char* at, int componentType)
{
  switch (componentType) {
  case TINYGLTF_COMPONENT_TYPE_BYTE:
    return loadAs<std::int8_t>(at);
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
    return loadAs<std::uint8_t>(at);
  case TINYGLTF_COMPONENT_TYPE_SHORT:
    return loadAs<std::int16_t>(at);
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
    return loadAs<std::uint16_t>(at);
  case TINYGLTF_COMPONENT_TYPE_INT:
    return loadAs<std::int32_t>(at);
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    return loadAs<std::uint32_t>(at);
  default:
    return loadAs<float>(at);
  }
}

bool isIndexType(int componentType)
{
  return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT || componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

/// The bytes of a buffer view, checked to lie inside its buffer.
struct ViewBytes
{
  const unsigned char* data = nullptr;
  std::size_t size = 0;
  std::size_t stride = 0;  ///< 0: tightly packed
};

ViewBytes viewBytes(const Source& s, int index, const std::string& what)
{
  if (index < 0 || static_cast<std::size_t>(index) >= s.model.bufferViews.size())
    fail(s, what + ": buffer view " + std::to_string(index) + " does not exist");
  const tinygltf::BufferView& view = s.model.bufferViews[static_cast<std::size_t>(index)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= s.model.buffers.size())
    fail(s, what + ": buffer view " + std::to_string(index) + " refers to a buffer that does not exist");
  const std::vector<unsigned char>& buffer = s.model.buffers[static_cast<std::size_t>(view.buffer)].data;
  if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
    fail(s, what + ": buffer view " + std::to_string(index) + " (" + std::to_string(view.byteLength) +
                " bytes from byte " + std::to_string(view.byteOffset) + ") runs past its " +
                std::to_string(buffer.size()) + "-byte buffer");
  return {buffer.data() + view.byteOffset, view.byteLength, view.byteStride};
}

/// The first of `count` elements of `elementBytes` bytes, `stride` apart from `offset` in `view`,
/// after checking that all of them lie inside it.
const unsigned char* elements(const Source& s, const ViewBytes& view, std::size_t offset, std::size_t count,
                              std::size_t elementBytes, std::size_t stride, const std::string& what)
{
  if (count == 0)
    return view.data;
  // Division, not multiplication, so a huge count cannot overflow into range.
  if (offset > view.size || elementBytes > view.size - offset ||
      count - 1 > (view.size - offset - elementBytes) / stride)
    fail(s, what + ": " + std::to_string(count) + " elements from byte " + std::to_string(offset) + " run past its " +
                std::to_string(view.size) + "-byte buffer view");
  return view.data + offset;
}

const tinygltf::Accessor& accessor(const Source& s, int index, const std::string& what)
{
  if (index < 0 || static_cast<std::size_t>(index) >= s.model.accessors.size())
    fail(s, what + ": accessor " + std::to_string(index) + " does not exist");
  return s.model.accessors[static_cast<std::size_t>(index)];
}

/// Substitutes the sparse entries of `a` into `values` (count × components).
void applySparse(const Source& s, const tinygltf::Accessor& a, int components, std::vector<double>& values,
                 const std::string& what)
{
  const auto& sparse = a.sparse;
  if (sparse.count < 0 || static_cast<std::size_t>(sparse.count) > a.count)
    fail(s, what + ": " + std::to_string(sparse.count) + " sparse entries for " + std::to_string(a.count) + " elements");
  if (!isIndexType(sparse.indices.componentType))
    fail(s, what + ": sparse indices must be unsigned byte, short or int");
  if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
    fail(s, what + ": negative sparse byte offset");
  const auto n = static_cast<std::size_t>(sparse.count);
  const std::size_t indexBytes = componentBytes(sparse.indices.componentType);
  const std::size_t valueBytes = componentBytes(a.componentType);
  const std::size_t elementBytes = valueBytes * static_cast<std::size_t>(components);
  const unsigned char* indices =
      elements(s, viewBytes(s, sparse.indices.bufferView, what + " sparse indices"),
               static_cast<std::size_t>(sparse.indices.byteOffset), n, indexBytes, indexBytes, what + " sparse indices");
  const unsigned char* substitutes =
      elements(s, viewBytes(s, sparse.values.bufferView, what + " sparse values"),
               static_cast<std::size_t>(sparse.values.byteOffset), n, elementBytes, elementBytes, what + " sparse values");
  chargeRead(s, std::uint64_t{n} * (indexBytes + elementBytes), what);
  for (std::size_t k = 0; k < n; ++k) {
    const double index = componentValue(indices + k * indexBytes, sparse.indices.componentType);
    if (index >= static_cast<double>(a.count))
      fail(s, what + ": sparse index " + std::to_string(static_cast<std::uint64_t>(index)) + " not below " +
                  std::to_string(a.count));
    const auto element = static_cast<std::size_t>(index);
    for (int c = 0; c < components; ++c)
      values[element * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)] = componentValue(
          substitutes + k * elementBytes + static_cast<std::size_t>(c) * valueBytes, a.componentType);
  }
}

/// The values of accessor `index` (count × components, row after row), sparse entries applied.
/// An accessor without a buffer view (zeros but its sparse entries) is read only where the
/// caller knows its count (`expectedCount`), so no count in a file makes us allocate more than
/// the file holds.
std::vector<double> accessorValues(const Source& s, int index, int components, std::optional<std::size_t> expectedCount,
                                   const std::string& what)
{
  const tinygltf::Accessor& a = accessor(s, index, what);
  if (tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)) != components)
    fail(s, what + ": accessor " + std::to_string(index) + " has " +
                std::to_string(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type))) +
                " components per element, not " + std::to_string(components));
  const std::size_t valueBytes = componentBytes(a.componentType);
  if (valueBytes == 0)
    fail(s, what + ": accessor " + std::to_string(index) + " has an unknown component type");
  if (expectedCount && a.count != *expectedCount)
    fail(s, what + ": accessor " + std::to_string(index) + " has " + std::to_string(a.count) + " elements, not " +
                std::to_string(*expectedCount));
  const std::size_t elementBytes = valueBytes * static_cast<std::size_t>(components);
  std::vector<double> values;
  if (a.bufferView >= 0) {
    const ViewBytes view = viewBytes(s, a.bufferView, what);
    const std::size_t stride = view.stride != 0 ? view.stride : elementBytes;
    if (stride < elementBytes)
      fail(s, what + ": byte stride " + std::to_string(stride) + " is less than its " + std::to_string(elementBytes) +
                  "-byte elements");
    const unsigned char* first = elements(s, view, a.byteOffset, a.count, elementBytes, stride, what);
    chargeRead(s, std::uint64_t{a.count} * elementBytes, what);
    values.resize(a.count * static_cast<std::size_t>(components));
    for (std::size_t i = 0; i < a.count; ++i)
      for (int c = 0; c < components; ++c)
        values[i * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)] =
            componentValue(first + i * stride + static_cast<std::size_t>(c) * valueBytes, a.componentType);
  } else if (!expectedCount) {
    fail(s, what + ": accessor " + std::to_string(index) + " has no buffer view");
  } else {
    values.assign(a.count * static_cast<std::size_t>(components), 0.0);
  }
  if (a.sparse.isSparse)
    applySparse(s, a, components, values, what);
  return values;
}

MeshVertices positions(const Source& s, int index, std::optional<std::size_t> expectedCount, const std::string& what)
{
  if (accessor(s, index, what).componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    fail(s, what + ": positions are not float (quantized meshes, KHR_mesh_quantization, are not read)");
  const std::vector<double> values = accessorValues(s, index, 3, expectedCount, what);
  MeshVertices vertices(static_cast<Eigen::Index>(values.size() / 3), 3);
  std::copy(values.begin(), values.end(), vertices.data());
  return vertices;
}

/// The primitive's corner indices: its index accessor, or 0, 1, 2, … without one.
std::vector<Eigen::Index> cornerIndices(const Source& s, const tinygltf::Primitive& primitive, Eigen::Index vertexCount,
                                        const std::string& what)
{
  std::vector<Eigen::Index> corners;
  if (primitive.indices < 0) {
    for (Eigen::Index v = 0; v < vertexCount; ++v)
      corners.push_back(v);
  } else {
    if (!isIndexType(accessor(s, primitive.indices, what).componentType))
      fail(s, what + ": indices must be unsigned byte, short or int");
    for (const double index : accessorValues(s, primitive.indices, 1, std::nullopt, what)) {
      if (index >= static_cast<double>(vertexCount))
        fail(s, what + ": index " + std::to_string(static_cast<std::uint64_t>(index)) + " not below its " +
                    std::to_string(vertexCount) + " vertices");
      corners.push_back(static_cast<Eigen::Index>(index));
    }
  }
  if (corners.size() % 3 != 0)
    fail(s, what + ": " + std::to_string(corners.size()) + " corners are not whole triangles");
  return corners;
}

std::optional<std::size_t> firstMeshWithTargets(const tinygltf::Model& model)
{
  for (std::size_t m = 0; m < model.meshes.size(); ++m)
    for (const tinygltf::Primitive& primitive : model.meshes[m].primitives)
      if (!primitive.targets.empty())
        return m;
  return std::nullopt;
}

/// The names in `extras.targetNames` when it has one string per target, else shape_0, shape_1, ….
std::vector<std::string> targetNames(const tinygltf::Mesh& mesh, std::size_t count)
{
  std::vector<std::string> names;
  if (mesh.extras.Has("targetNames")) {
    const tinygltf::Value& list = mesh.extras.Get("targetNames");
    if (list.IsArray() && list.ArrayLen() == count)
      for (std::size_t t = 0; t < count && list.Get(static_cast<int>(t)).IsString(); ++t)
        names.push_back(list.Get(static_cast<int>(t)).Get<std::string>());
  }
  if (names.size() != count) {
    names.clear();
    for (std::size_t t = 0; t < count; ++t)
      names.push_back("shape_" + std::to_string(t));
  }
  return names;
}

std::string primitiveName(std::size_t mesh, std::size_t primitive)
{
  return "mesh " + std::to_string(mesh) + " primitive " + std::to_string(primitive);
}

int positionAttribute(const Source& s, const tinygltf::Primitive& primitive, const std::string& what)
{
  const auto it = primitive.attributes.find("POSITION");
  if (it == primitive.attributes.end())
    fail(s, what + " has no POSITION attribute");
  return it->second;
}

/// The merged neutral; `offsets` gets each primitive's first vertex (and the total at the end).
Mesh mergedNeutral(const Source& s, std::size_t meshIndex, std::vector<Eigen::Index>& offsets)
{
  const tinygltf::Mesh& mesh = s.model.meshes[meshIndex];
  std::vector<MeshVertices> blocks;
  Mesh neutral;
  offsets.assign(1, 0);
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    const tinygltf::Primitive& primitive = mesh.primitives[p];
    const std::string what = primitiveName(meshIndex, p);
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES)
      fail(s, what + " draws mode " + std::to_string(primitive.mode) + "; only triangles (mode 4) are read");
    blocks.push_back(positions(s, positionAttribute(s, primitive, what), std::nullopt, what + " POSITION"));
    const std::vector<Eigen::Index> corners = cornerIndices(s, primitive, blocks.back().rows(), what);
    for (std::size_t c = 0; c < corners.size(); c += 3) {
      const Eigen::Index a = corners[c], b = corners[c + 1], d = corners[c + 2];
      if (a != b && b != d && a != d)  // a repeated index spans no area
        neutral.faces.push_back({{offsets.back() + a, offsets.back() + b, offsets.back() + d}, {}, {}});
    }
    offsets.push_back(offsets.back() + blocks.back().rows());
  }
  if (neutral.faces.empty())
    fail(s, "mesh " + std::to_string(meshIndex) + " has no triangles");
  neutral.vertices.resize(offsets.back(), 3);
  for (std::size_t p = 0; p < blocks.size(); ++p)
    neutral.vertices.middleRows(offsets[p], blocks[p].rows()) = blocks[p];
  return neutral;
}

/// Morph target `t` of every primitive as one sparse shape over the merged vertices.
SparseShape mergedTarget(const Source& s, std::size_t meshIndex, std::size_t t, const std::vector<Eigen::Index>& offsets,
                         std::string name)
{
  const tinygltf::Mesh& mesh = s.model.meshes[meshIndex];
  MeshVertices deltas = MeshVertices::Zero(offsets.back(), 3);
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    const std::map<std::string, int>& target = mesh.primitives[p].targets[t];
    const auto it = target.find("POSITION");
    if (it == target.end())
      continue;  // a target of normals only moves no vertex
    const Eigen::Index count = offsets[p + 1] - offsets[p];
    deltas.middleRows(offsets[p], count) =
        positions(s, it->second, static_cast<std::size_t>(count),
                  primitiveName(meshIndex, p) + " target " + std::to_string(t) + " POSITION");
  }
  SparseShape shape;
  shape.name = std::move(name);
  for (Eigen::Index v = 0; v < deltas.rows(); ++v)
    if (deltas.row(v).cwiseAbs().maxCoeff() > 0.0 || !deltas.row(v).allFinite())  // non-finite: checkRig reports it
      shape.vertices.push_back(v);
  shape.deltas.resize(shape.size(), 3);
  for (Eigen::Index i = 0; i < shape.size(); ++i)
    shape.deltas.row(i) = deltas.row(shape.vertices[static_cast<std::size_t>(i)]);
  return shape;
}

BlendshapeRig buildRig(const Source& s)
{
  const std::optional<std::size_t> meshIndex = firstMeshWithTargets(s.model);
  if (!meshIndex)
    fail(s, "no mesh with morph targets (shape keys)");
  const tinygltf::Mesh& mesh = s.model.meshes[*meshIndex];
  const std::size_t targetCount = mesh.primitives.front().targets.size();
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
    if (mesh.primitives[p].targets.size() != targetCount)
      fail(s, primitiveName(*meshIndex, p) + " has " + std::to_string(mesh.primitives[p].targets.size()) +
                  " morph targets, primitive 0 has " + std::to_string(targetCount));
  BlendshapeRig rig;
  std::vector<Eigen::Index> offsets;
  rig.neutral = mergedNeutral(s, *meshIndex, offsets);
  std::vector<std::string> names = targetNames(mesh, targetCount);
  for (std::size_t t = 0; t < targetCount; ++t)
    rig.shapes.push_back(mergedTarget(s, *meshIndex, t, offsets, std::move(names[t])));
  return rig;
}

} // namespace

BlendshapeRig parseGltfRig(std::string_view bytes, const std::string& sourceName, const std::filesystem::path& baseDir,
                           const std::vector<std::string>& only)
{
  const tinygltf::Model model = loadModel(bytes, sourceName, baseDir);
  refuseGeometryExtensions(model, sourceName);
  ReadBudget budget(model);
  BlendshapeRig rig = buildRig({model, sourceName, budget});
  try {
    checkRig(rig);
  } catch (const InvalidArgument& e) {
    throw FormatError(sourceName, e.what());  // the file's content, not the caller, is wrong
  }
  return only.empty() ? rig : selectShapes(rig, only);
}

BlendshapeRig readGltfRig(const std::filesystem::path& path, const std::vector<std::string>& only)
{
  const MappedFile file(path);
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  return parseGltfRig(std::string_view(reinterpret_cast<const char*>(file.data()), file.size()), path.string(), folder,
                      only);
}

} // namespace mocap
