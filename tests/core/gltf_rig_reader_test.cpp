// readGltfRig: our own GLB read back, the .gltf forms, the accessor layouts other exporters use
// (strides, offsets, dense and sparse targets, several primitives) and bad files. The layouts are
// built with TinyGLTF's model and writer, so each test states exactly what the file holds.
#include "face_mesh_fixture.h"
#include "glb_model.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/io/gltf_rig_reader.h"
#include "mocap/io/gltf_writer.h"
#include "mocap/io/mesh_io.h"
#include "mocap/io/rig_io.h"

#include <gtest/gtest.h>

#include <tiny_gltf.h>

#include <cstring>
#include <functional>
#include <map>
#include <sstream>

namespace mocap {
namespace {

BlendshapeRig threeShapeRig()
{
  const Mesh& face = test::mediaPipeFace();
  BlendshapeRig rig;
  rig.neutral = face;
  const char* names[] = {"jawOpen", "browInnerUp"};
  for (int s = 0; s < 2; ++s) {
    MeshVertices posed = face.vertices;
    const Eigen::RowVector3d centre = face.vertices.row(40 + 150 * s);
    for (Eigen::Index v = 0; v < posed.rows(); ++v) {
      const double falloff = std::exp(-(posed.row(v) - centre).squaredNorm() / 9.0);
      if (falloff > 1e-3)
        posed(v, s) += 0.6 * falloff;
    }
    rig.shapes.push_back(sparseShape(names[s], face.vertices, posed, 1e-9));
  }
  rig.shapes.push_back(sparseShape("still", face.vertices, face.vertices, 1e-9));
  return rig;
}

double asFloat(double value)
{
  return static_cast<double>(static_cast<float>(value));
}

/// The rig as GLB holds it: every coordinate rounded to float32.
void expectSameRigAsFloat(const BlendshapeRig& read, const BlendshapeRig& rig)
{
  ASSERT_EQ(read.neutral.vertexCount(), rig.neutral.vertexCount());
  EXPECT_EQ(read.neutral.triangles(), rig.neutral.triangles());
  EXPECT_EQ(read.neutral.vertices, rig.neutral.vertices.unaryExpr(&asFloat));
  ASSERT_EQ(read.shapeNames(), rig.shapeNames());
  for (std::size_t s = 0; s < rig.shapes.size(); ++s) {
    EXPECT_EQ(read.shapes[s].vertices, rig.shapes[s].vertices) << rig.shapes[s].name;
    EXPECT_EQ(read.shapes[s].deltas, rig.shapes[s].deltas.unaryExpr(&asFloat)) << rig.shapes[s].name;
  }
}

/// Expects `read` to throw `Expected` with `fragment` in its message.
template <typename Expected>
void expectError(const std::function<void()>& read, const std::string& fragment)
{
  try {
    read();
    ADD_FAILURE() << "no error; expected one saying '" << fragment << "'";
  } catch (const Expected& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(GltfRigReader, ReadsBackTheRigOurWriterWrote)
{
  const BlendshapeRig rig = threeShapeRig();
  const std::string glb = rigGlb(rig, Eigen::MatrixXd(0, 3), 30.0);
  expectSameRigAsFloat(parseGltfRig(glb, "rig.glb"), rig);
  EXPECT_GT(rig.shapes[0].size(), 10);
  EXPECT_EQ(parseGltfRig(glb, "rig.glb").shapes[2].size(), 0);  // a target without data moves nothing
  EXPECT_EQ(rigGlb(parseGltfRig(glb, "rig.glb"), Eigen::MatrixXd(0, 3), 30.0), glb);  // nothing lost or added

  const test::TempDir dir;
  writeRigGlb(dir.file("rig.glb"), rig, Eigen::MatrixXd::Constant(4, 3, 0.5), 30.0);  // an animation is skipped
  expectSameRigAsFloat(readGltfRig(dir.file("rig.glb")), rig);
  EXPECT_EQ(readGltfRig(dir.file("rig.glb"), {"still", "jawOpen"}).shapeNames(),
            (std::vector<std::string>{"still", "jawOpen"}));
  EXPECT_EQ(readRig(dir.file("rig.glb"), {}).shapeCount(), 3);
  EXPECT_EQ(readMesh(dir.file("rig.glb")).triangles(), rig.neutral.triangles());
  expectError<InvalidArgument>([&] { (void)readGltfRig(dir.file("rig.glb"), {"smile"}); }, "no shape called 'smile'");
  expectError<InvalidArgument>([&] { (void)readRig(dir.file("rig.glb"), dir.path()); }, "no shape folder");
}

TEST(GltfRigReader, ReadsTheJsonFormWithAnExternalOrAnEmbeddedBuffer)
{
  const BlendshapeRig rig = threeShapeRig();
  const tinygltf::Model model = test::glbModel(rigGlb(rig, Eigen::MatrixXd(0, 3), 30.0));
  const test::TempDir dir;
  tinygltf::TinyGLTF writer;
  ASSERT_TRUE(writer.WriteGltfSceneToFile(&model, dir.file("external.gltf").string(), false, false, true, false));
  ASSERT_TRUE(std::filesystem::exists(dir.file("external.bin")));
  expectSameRigAsFloat(readGltfRig(dir.file("external.gltf")), rig);
  ASSERT_TRUE(writer.WriteGltfSceneToFile(&model, dir.file("embedded.gltf").string(), false, true, true, false));
  const std::string embedded = readFileBytes(dir.file("embedded.gltf"));
  EXPECT_NE(embedded.find("data:application/octet-stream;base64,"), std::string::npos);
  expectSameRigAsFloat(parseGltfRig(embedded, "embedded.gltf"), rig);
  // Bytes parsed without a folder read no other file.
  expectError<FormatError>([&] { (void)parseGltfRig(readFileBytes(dir.file("external.gltf")), "external.gltf"); },
                           "external.bin");
}

/// A glTF model built piece by piece in one buffer, for layouts our writer does not produce.
struct ModelBuilder
{
  tinygltf::Model model;

  ModelBuilder()
  {
    model.asset.version = "2.0";
    model.buffers.emplace_back();
    model.meshes.emplace_back();
  }

  /// A view over `values`, after `padding` bytes of its own; `stride` 0: tightly packed.
  template <typename T>
  int view(const std::vector<T>& values, std::size_t padding = 0, std::size_t stride = 0)
  {
    std::vector<unsigned char>& data = model.buffers[0].data;
    data.resize((data.size() + 3) / 4 * 4);
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = data.size();
    v.byteLength = padding + values.size() * sizeof(T);
    v.byteStride = stride;
    data.resize(data.size() + padding, 0xEE);
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    data.insert(data.end(), bytes, bytes + values.size() * sizeof(T));
    model.bufferViews.push_back(v);
    return static_cast<int>(model.bufferViews.size()) - 1;
  }

  int accessor(int bufferView, int componentType, int type, std::size_t count, std::size_t byteOffset = 0)
  {
    tinygltf::Accessor a;
    a.bufferView = bufferView;
    a.componentType = componentType;
    a.type = type;
    a.count = count;
    a.byteOffset = byteOffset;
    model.accessors.push_back(a);
    return static_cast<int>(model.accessors.size()) - 1;
  }

  int floats3(const std::vector<float>& values) { return accessor(view(values), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, values.size() / 3); }

  void sparse(int accessorIndex, int indexType, int indexView, int valueView, int count)
  {
    auto& s = model.accessors[static_cast<std::size_t>(accessorIndex)].sparse;
    s.isSparse = true;
    s.count = count;
    s.indices.bufferView = indexView;
    s.indices.byteOffset = 0;
    s.indices.componentType = indexType;
    s.values.bufferView = valueView;
    s.values.byteOffset = 0;
  }

  tinygltf::Primitive& primitive(int positions, int indices = -1)
  {
    tinygltf::Primitive p;
    p.mode = TINYGLTF_MODE_TRIANGLES;
    p.attributes["POSITION"] = positions;
    p.indices = indices;
    model.meshes[0].primitives.push_back(p);
    return model.meshes[0].primitives.back();
  }

  void names(const std::vector<std::string>& list)
  {
    std::vector<tinygltf::Value> values(list.begin(), list.end());
    model.meshes[0].extras = tinygltf::Value(tinygltf::Value::Object{{"targetNames", tinygltf::Value(values)}});
  }

  [[nodiscard]] std::string glb() const
  {
    std::ostringstream out;
    EXPECT_TRUE(tinygltf::TinyGLTF().WriteGltfSceneToStream(&model, out, false, true));
    return out.str();
  }
};

/// Two primitives laid out as other exporters do. Primitive 0: a quad of 4 vertices interleaved
/// with 3 other floats (stride 24, positions at byte 12 of a view that starts after 8 bytes),
/// unsigned-byte indices with one zero-area triangle, target 0 dense, target 1 sparse over zeros
/// (unsigned-short index). Primitive 1: 3 vertices without indices, target 0 of normals only,
/// target 1 dense base values with a sparse substitution (unsigned-byte index).
ModelBuilder twoPrimitiveModel()
{
  ModelBuilder b;
  std::vector<float> interleaved;
  const float quad[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (const auto& p : quad)
    interleaved.insert(interleaved.end(), {9.0f, 9.0f, 9.0f, p[0], p[1], p[2]});
  const int quadPositions = b.accessor(b.view(interleaved, 8, 24), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 4, 8 + 12);
  const int quadIndices = b.accessor(b.view(std::vector<std::uint8_t>{0, 1, 2, 0, 2, 3, 1, 1, 2}),
                                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_SCALAR, 9);
  tinygltf::Primitive& first = b.primitive(quadPositions, quadIndices);
  const int dense = b.floats3({0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0});
  const int sparse = b.accessor(-1, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 4);
  const int sparseIndices = b.view(std::vector<std::uint16_t>{3});  // views made in turn: 3, then 4
  b.sparse(sparse, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, sparseIndices, b.view(std::vector<float>{0, 0, 2}), 1);
  first.targets = {{{"POSITION", dense}}, {{"POSITION", sparse}}};

  const int triangle = b.floats3({0, 0, 1, 1, 0, 1, 0, 1, 1});
  tinygltf::Primitive& second = b.primitive(triangle);
  const int normals = b.floats3({0, 0, 1, 0, 0, 1, 0, 0, 1});
  const int based = b.floats3({1, 0, 0, 0, 0, 0, 0, 0, 0});
  const int basedIndices = b.view(std::vector<std::uint8_t>{2, 0, 0, 0});
  b.sparse(based, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, basedIndices, b.view(std::vector<float>{0, 0, -1}), 1);
  second.targets = {{{"NORMAL", normals}}, {{"POSITION", based}}};
  b.names({"onlyOneName"});  // the wrong count: shape_0, shape_1
  return b;
}

TEST(GltfRigReader, MergesPrimitivesAndReadsStridedDenseAndSparseAccessors)
{
  const BlendshapeRig rig = parseGltfRig(twoPrimitiveModel().glb(), "layouts.glb");
  ASSERT_EQ(rig.neutral.vertexCount(), 7);
  EXPECT_EQ(rig.neutral.vertices.row(2), Eigen::RowVector3d(1, 1, 0));
  EXPECT_EQ(rig.neutral.vertices.row(5), Eigen::RowVector3d(1, 0, 1));
  EXPECT_EQ(rig.neutral.triangles(), (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}, {4, 5, 6}}));
  ASSERT_EQ(rig.shapeNames(), (std::vector<std::string>{"shape_0", "shape_1"}));
  EXPECT_EQ(rig.shapes[0].vertices, std::vector<Eigen::Index>{1});
  EXPECT_EQ(rig.shapes[0].deltaOf(1), Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(rig.shapes[1].vertices, (std::vector<Eigen::Index>{3, 4, 6}));
  EXPECT_EQ(rig.shapes[1].deltaOf(3), Eigen::Vector3d(0, 0, 2));
  EXPECT_EQ(rig.shapes[1].deltaOf(4), Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(rig.shapes[1].deltaOf(6), Eigen::Vector3d(0, 0, -1));
}

void expectModelError(const std::function<void(ModelBuilder&)>& breakIt, const std::string& fragment)
{
  ModelBuilder b = twoPrimitiveModel();
  breakIt(b);
  const std::string glb = b.glb();
  expectError<FormatError>([&] { (void)parseGltfRig(glb, "broken.glb"); }, fragment);
}

TEST(GltfRigReader, RefusesAccessorsAndViewsOutsideTheirBuffers)
{
  expectModelError([](ModelBuilder& b) { b.model.accessors[0].count = 40; }, "run past its");
  expectModelError([](ModelBuilder& b) { b.model.accessors[0].byteOffset = 1u << 30; }, "run past its");
  expectModelError([](ModelBuilder& b) { b.model.bufferViews[0].byteLength = 1u << 20; }, "runs past its");
  expectModelError([](ModelBuilder& b) { b.model.bufferViews[0].byteStride = 8; }, "byte stride 8 is less than");
  expectModelError([](ModelBuilder& b) { b.model.meshes[0].primitives[0].targets[0]["POSITION"] = 99; },
                   "accessor 99 does not exist");
  expectModelError([](ModelBuilder& b) { b.model.accessors[3].sparse.count = 9; }, "sparse entries for 4");
  expectModelError([](ModelBuilder& b) { b.model.accessors[3].sparse.indices.bufferView = 40; },
                   "buffer view 40 does not exist");
  expectModelError([](ModelBuilder& b) { b.model.buffers[0].data[b.model.bufferViews[3].byteOffset] = 7; },
                   "sparse index 7 not below 4");
  expectModelError([](ModelBuilder& b) { b.model.buffers[0].data[b.model.bufferViews[1].byteOffset] = 4; },
                   "index 4 not below its 4 vertices");
  expectModelError([](ModelBuilder& b) { b.model.accessors[1].count = 8; }, "not whole triangles");
}

TEST(GltfRigReader, RefusesWhatIsNotATriangleRigWithFloatPositions)
{
  expectModelError([](ModelBuilder& b) { b.model.meshes[0].primitives[1].mode = TINYGLTF_MODE_LINE; },
                   "primitive 1 draws mode 1; only triangles");
  expectModelError([](ModelBuilder& b) { b.model.meshes[0].primitives[1].targets.pop_back(); },
                   "primitive 1 has 1 morph targets, primitive 0 has 2");
  expectModelError(
      [](ModelBuilder& b) {
        for (tinygltf::Primitive& p : b.model.meshes[0].primitives)
          p.targets.clear();
      },
      "no mesh with morph targets");
  expectModelError(
      [](ModelBuilder& b) {
        b.model.accessors[0].componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        b.model.accessors[0].normalized = true;
      },
      "KHR_mesh_quantization");
  expectModelError([](ModelBuilder& b) { b.model.extensionsRequired.push_back("KHR_draco_mesh_compression"); },
                   "requires KHR_draco_mesh_compression");
  expectModelError([](ModelBuilder& b) { b.names({"smile", "smile"}); }, "two shapes called 'smile'");
  expectModelError([](ModelBuilder& b) { b.model.meshes[0].primitives[0].attributes = {{"NORMAL", 5}}; }, "no POSITION");
  expectModelError(
      [](ModelBuilder& b) {
        const float nan = std::nanf("");
        std::memcpy(&b.model.buffers[0].data[b.model.bufferViews[2].byteOffset + 4], &nan, sizeof nan);
      },
      "non-finite");
  // A second mesh without targets comes first: the rig is still found, names and all.
  ModelBuilder b = twoPrimitiveModel();
  b.names({"up", "out"});
  tinygltf::Mesh still;
  still.primitives.push_back(b.model.meshes[0].primitives[1]);
  still.primitives[0].targets.clear();
  b.model.meshes.insert(b.model.meshes.begin(), still);
  EXPECT_EQ(parseGltfRig(b.glb(), "two_meshes.glb").shapeNames(), (std::vector<std::string>{"up", "out"}));
}

/// A neutral of `vertices` vertices drawn without indices and `targets` morph targets that all
/// name one dense accessor moving every vertex: the file holds 24 bytes per vertex, whatever the
/// number of targets.
std::string sharedTargetGlb(std::size_t vertices, std::size_t targets)
{
  ModelBuilder b;
  std::vector<float> neutral(vertices * 3);
  for (std::size_t i = 0; i < neutral.size(); ++i)
    neutral[i] = static_cast<float>(i % 97);
  tinygltf::Primitive& primitive = b.primitive(b.floats3(neutral));
  const int shared = b.floats3(std::vector<float>(vertices * 3, 0.5f));
  primitive.targets.assign(targets, std::map<std::string, int>{{"POSITION", shared}});
  return b.glb();
}

TEST(GltfRigReader, ReadsTargetsThatShareAnAccessor)
{
  // Deduplicating tools (gltf-transform dedup) give identical targets one accessor.
  const BlendshapeRig rig = parseGltfRig(sharedTargetGlb(300, 4), "dedup.glb");
  ASSERT_EQ(rig.shapeCount(), 4);
  EXPECT_EQ(rig.shapes[3].size(), 300);
  EXPECT_EQ(rig.shapes[3].deltas, rig.shapes[0].deltas);
}

TEST(GltfRigReader, RefusesTargetsThatReuseOneAccessorFarBeyondWhatTheFileHolds)
{
  // 24 KB of buffers; read in full, 2000 targets would hold 2000 × 999 moved vertices (64 MB).
  const std::string glb = sharedTargetGlb(999, 2000);
  ASSERT_LT(glb.size(), 100'000u);
  try {
    (void)parseGltfRig(glb, "hostile.glb");
    ADD_FAILURE() << "a rig that reuses one accessor 2000 times loaded";
  } catch (const FormatError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("hostile.glb: mesh 0 primitive 0 target "), std::string::npos) << message;
    EXPECT_NE(message.find("bytes of accessor data from buffers of 23976 bytes; its primitives or morph targets "
                           "reuse accessors too often"),
              std::string::npos)
        << message;
    // Refused before the expansion: at the first target past the limit, not after all 2000.
    const std::size_t at = message.find("target ") + std::string("target ").size();
    EXPECT_LT(std::stoi(message.substr(at)), 50) << message;
  }
}

TEST(GltfRigReader, RefusesTruncatedGarbageAndMissingFiles)
{
  const std::string glb = rigGlb(threeShapeRig(), Eigen::MatrixXd(0, 3), 30.0);
  expectError<FormatError>([&] { (void)parseGltfRig(glb.substr(0, glb.size() / 2), "cut.glb"); },
                           "cut.glb: truncated GLB: the header gives " + std::to_string(glb.size()) + " bytes");
  expectError<FormatError>([&] { (void)parseGltfRig(glb.substr(0, 10), "stub.glb"); }, "truncated GLB: 10 bytes");
  std::string chunk = glb;
  std::uint32_t jsonLength = 0;
  std::memcpy(&jsonLength, glb.data() + 12, sizeof jsonLength);  // little-endian, as the host
  chunk[20 + jsonLength + 3] = '\x7f';  // the BIN chunk's length, now past the end
  expectError<FormatError>([&] { (void)parseGltfRig(chunk, "chunk.glb"); }, "chunk runs past its end");
  std::string version = glb;
  version[4] = 1;
  expectError<FormatError>([&] { (void)parseGltfRig(version, "old.glb"); }, "GLB version 1");
  expectError<FormatError>([&] { (void)parseGltfRig("\x01\x02 not a model at all", "garbage.gltf"); },
                           "garbage.gltf: not a readable glTF 2.0 file");
  expectError<FormatError>([&] { (void)parseGltfRig("", "empty.glb"); }, "not a readable glTF");
  expectError<IoError>([] { (void)readGltfRig("/nonexistent/rig.glb"); }, "/nonexistent/rig.glb");
  const test::TempDir dir;
  writeFileAtomically(dir.file("junk.glb"), "glTF but not really");
  expectError<FormatError>([&] { (void)readMesh(dir.file("junk.glb")); }, "junk.glb");
}

} // namespace
} // namespace mocap
