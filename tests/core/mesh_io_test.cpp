#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/io/mesh_io.h"
#include "mocap/io/obj_io.h"
#include "mocap/io/pc2_io.h"
#include "mocap/io/ply_io.h"

#include <gtest/gtest.h>

#include <cstring>

namespace mocap {
namespace {

std::filesystem::path mediaPipeMesh()
{
  return test::dataFile("face_mesh/canonical_face_model.obj");
}

// A quad and a triangle with UVs and normals, non-representable decimals included.
Mesh quadAndTriangle()
{
  Mesh mesh;
  mesh.vertices.resize(5, 3);
  mesh.vertices << 0, 0, 0, 1.1, 0, 0, 1.1, 0.1 + 0.2, 0, 0, 1, 1.0 / 3.0, 2, 2, -7e-300;
  mesh.uvs.resize(4, 2);
  mesh.uvs << 0, 0, 1, 0, 1, 1, 0, 1;
  mesh.normals.resize(1, 3);
  mesh.normals << 0, 0, 1;
  mesh.faces.push_back({{0, 1, 2, 3}, {0, 1, 2, 3}, {0, 0, 0, 0}});
  mesh.faces.push_back({{1, 4, 2}, {}, {}});
  return mesh;
}

void expectSameFaces(const Mesh& a, const Mesh& b, bool withAttributes)
{
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (std::size_t f = 0; f < a.faces.size(); ++f) {
    EXPECT_EQ(a.faces[f].vertices, b.faces[f].vertices);
    if (withAttributes) {
      EXPECT_EQ(a.faces[f].uvs, b.faces[f].uvs);
      EXPECT_EQ(a.faces[f].normals, b.faces[f].normals);
    }
  }
}

TEST(MeshIo, ReadsTheMediaPipeCanonicalFace)
{
  const Mesh mesh = readMesh(mediaPipeMesh());
  EXPECT_EQ(mesh.vertexCount(), 468);
  EXPECT_EQ(mesh.uvs.rows(), 468);
  EXPECT_EQ(mesh.faces.size(), 898u);
  EXPECT_EQ(mesh.triangles().size(), 898u);
  EXPECT_NO_THROW(checkMesh(mesh));
  // Units cm, about 15.5 × 17.7 cm (tests/data/SOURCES.md).
  EXPECT_GT(mesh.size(), 20.0);
  EXPECT_LT(mesh.size(), 30.0);
}

TEST(MeshIo, ObjRoundTripKeepsQuadsUvsNormalsAndExactNumbers)
{
  test::TempDir dir;
  const Mesh mesh = quadAndTriangle();
  writeObj(dir.file("m.obj"), mesh);
  const Mesh back = readObj(dir.file("m.obj"));
  EXPECT_EQ(back.vertices, mesh.vertices);  // bit for bit: shortest round-trip text
  EXPECT_EQ(back.uvs, mesh.uvs);
  EXPECT_EQ(back.normals, mesh.normals);
  expectSameFaces(mesh, back, true);
  EXPECT_EQ(back.triangles().size(), 3u);  // the quad is a fan of two
}

TEST(MeshIo, ObjReadsNegativeIndicesAndSkipsOtherStatements)
{
  test::TempDir dir;
  writeFileAtomically(dir.file("n.obj"), "# c\nmtllib x.mtl\no thing\nv 0 0 0\nv 1 0 0\nv 0 1 0 1.0\nvn 0 0 1\n"
                                         "g group\nusemtl m\ns off\nf -3//1 -2//1 -1//1\n");
  const Mesh mesh = readObj(dir.file("n.obj"));
  ASSERT_EQ(mesh.faces.size(), 1u);
  EXPECT_EQ(mesh.faces[0].vertices, (std::vector<Eigen::Index>{0, 1, 2}));
  EXPECT_EQ(mesh.faces[0].normals, (std::vector<Eigen::Index>{0, 0, 0}));
  EXPECT_TRUE(mesh.faces[0].uvs.empty());
}

TEST(MeshIo, MalformedObjGivesLineNumberedErrors)
{
  test::TempDir dir;
  const std::pair<const char*, const char*> cases[] = {
      {"v 0 0 0\nv 1 0 0\nf 1 2 3\n", "line 3: vertex index 3 out of range"},
      {"v 0 0 x\n", "line 1: expected a finite number"},
      {"v 0 0 nan\n", "line 1: expected a finite number"},
      {"v 0 0 0\nv 1 0 0\nf 1 2\n", "at least 3 corners"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1\n", "repeats vertex 1"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", "bad vertex index"},
  };
  for (const auto& [text, message] : cases) {
    writeFileAtomically(dir.file("bad.obj"), text);
    try {
      (void)readObj(dir.file("bad.obj"));
      ADD_FAILURE() << "accepted: " << text;
    } catch (const FormatError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW((void)readObj(dir.file("missing.obj")), IoError);
  EXPECT_THROW((void)readMesh(dir.file("mesh.stl")), InvalidArgument);
}

TEST(MeshIo, PlyBinaryRoundTripIsExact)
{
  test::TempDir dir;
  const Mesh mesh = quadAndTriangle();
  writePly(dir.file("m.ply"), mesh, mesh.vertices);
  const Mesh back = readPly(dir.file("m.ply"));
  EXPECT_EQ(back.vertices, mesh.vertices);
  expectSameFaces(mesh, back, false);
}

TEST(MeshIo, PlyAsciiWithExtraPropertiesAndElements)
{
  test::TempDir dir;
  writeFileAtomically(dir.file("a.ply"), "ply\nformat ascii 1.0\ncomment hi\nelement vertex 4\nproperty float x\n"
                                         "property float y\nproperty float z\nproperty uchar red\n"
                                         "element face 1\nproperty list uchar int vertex_indices\n"
                                         "element edge 1\nproperty int a\nproperty int b\nend_header\n"
                                         "0 0 0 255\n1 0 0 0\n1 1 0 0\n0 1 0.5 7\n4 0 1 2 3\n0 1\n");
  const Mesh mesh = readPly(dir.file("a.ply"));
  ASSERT_EQ(mesh.vertexCount(), 4);
  EXPECT_EQ(mesh.vertices(3, 2), 0.5);
  ASSERT_EQ(mesh.faces.size(), 1u);
  EXPECT_EQ(mesh.faces[0].vertices.size(), 4u);
}

TEST(MeshIo, MalformedPlyIsRejected)
{
  test::TempDir dir;
  const char* cases[] = {
      "plx\n",
      "ply\nformat binary_big_endian 1.0\nelement vertex 0\nend_header\n",
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n",
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n",
      "ply\nformat binary_little_endian 1.0\nelement vertex 5\nproperty double x\nproperty double y\n"
      "property double z\nend_header\n\x01\x02",
      // Found by fuzz_ply_reader: a corner index beyond Eigen::Index was converted (undefined).
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
      "3 0 1 11111111111111111111111111111111111111\n",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar float vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1.5\n",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar float vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 nan\n",
  };
  for (const char* text : cases) {
    writeFileAtomically(dir.file("bad.ply"), text);
    EXPECT_THROW((void)readPly(dir.file("bad.ply")), FormatError) << text;
  }
}

TEST(MeshIo, Pc2WrittenIsReadBackBitForBit)
{
  test::TempDir dir;
  const Mesh mesh = readMesh(mediaPipeMesh());
  std::vector<MeshVertices> frames;
  {
    Pc2Writer writer(dir.file("c.pc2"), mesh.vertexCount(), 12.0f, 1.0f);
    for (int f = 0; f < 3; ++f) {
      frames.push_back(mesh.vertices + MeshVertices::Random(mesh.vertexCount(), 3) * 0.37);
      writer.addFrame(frames.back());
    }
    writer.finish();
  }
  const PointCache cache = readPc2(dir.file("c.pc2"));
  EXPECT_EQ(cache.startFrame, 12.0f);
  EXPECT_EQ(cache.sampleRate, 1.0f);
  ASSERT_EQ(cache.samples.size(), 3u);
  for (std::size_t f = 0; f < 3; ++f) {
    const Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor> expected = frames[f].cast<float>();
    ASSERT_EQ(cache.samples[f].rows(), mesh.vertexCount());
    EXPECT_EQ(std::memcmp(cache.samples[f].data(), expected.data(), sizeof(float) * 3 * 468), 0);
  }
  // Writing what was read gives the same bytes.
  {
    Pc2Writer writer(dir.file("d.pc2"), mesh.vertexCount(), cache.startFrame, cache.sampleRate);
    for (const auto& sample : cache.samples)
      writer.addFrame(sample.cast<double>());
    writer.finish();
  }
  EXPECT_EQ(readFileBytes(dir.file("c.pc2")), readFileBytes(dir.file("d.pc2")));
  EXPECT_EQ(readFileBytes(dir.file("c.pc2")).size(), 32u + 3u * 468u * 12u);
}

TEST(MeshIo, Pc2WriterLeavesNoFileWithoutFinishAndRejectsBadInput)
{
  test::TempDir dir;
  {
    Pc2Writer writer(dir.file("x.pc2"), 3, 0.0f, 1.0f);
    writer.addFrame(MeshVertices::Zero(3, 3));
    EXPECT_THROW(writer.addFrame(MeshVertices::Zero(2, 3)), InvalidArgument);
    MeshVertices bad = MeshVertices::Zero(3, 3);
    bad(1, 1) = std::nan("");
    EXPECT_THROW(writer.addFrame(bad), InvalidArgument);
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.pc2")));
  std::size_t leftovers = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path()))
    ++leftovers;
  EXPECT_EQ(leftovers, 0u);
  writeFileAtomically(dir.file("short.pc2"), std::string("POINTCACHE2\0", 12) + std::string(20, '\0') + "xyz");
  EXPECT_THROW((void)readPc2(dir.file("short.pc2")), FormatError);
  writeFileAtomically(dir.file("magic.pc2"), std::string(40, 'x'));
  EXPECT_THROW((void)readPc2(dir.file("magic.pc2")), FormatError);

  // Found by fuzz_pc2_reader: a header claiming samples of zero points (the reader copied each
  // empty sample from a null pointer, and 2^31 of them fit in 32 bytes).
  std::string header("POINTCACHE2\0\1\0\0\0", 16);
  header += std::string(8, '\0') + std::string("\0\0\x80\x3f", 4);  // 0 points, start 0, rate 1
  EXPECT_THROW((void)parsePc2(header + std::string("\xff\xff\xff\x7f", 4), "many.pc2"), FormatError);
  EXPECT_THROW((void)parsePc2(header + std::string("\2\0\0\0", 4), "two.pc2"), FormatError);
  EXPECT_TRUE(parsePc2(header + std::string(4, '\0'), "empty.pc2").samples.empty());
}

} // namespace
} // namespace mocap
