// MeshSequenceWriter: each format reads back frame for frame, and an unfinished writer leaves
// nothing behind.
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/io/mesh_sequence_writer.h"
#include "mocap/io/obj_io.h"
#include "mocap/io/pc2_io.h"
#include "mocap/io/ply_io.h"

#include <gtest/gtest.h>

namespace mocap {
namespace {

namespace fs = std::filesystem;

Mesh triangle()
{
  Mesh mesh;
  mesh.vertices.resize(3, 3);
  mesh.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  mesh.faces.push_back({{0, 1, 2}, {}, {}});
  return mesh;
}

// Frame f: the triangle moved by (f, 2f, −f/4) and its second vertex lifted by f/8.
MeshVertices frameOf(const Mesh& mesh, int f)
{
  MeshVertices v = mesh.vertices;
  v.rowwise() += Eigen::RowVector3d(f, 2.0 * f, -0.25 * f);
  v(1, 2) += f / 8.0;
  return v;
}

TEST(MeshSequenceWriter, PointCacheHoldsEveryFrameAndTheRestObjBesideIt)
{
  test::TempDir dir;
  const Mesh mesh = triangle();
  const fs::path cache = dir.file("anim.pc2");
  {
    MeshSequenceWriter writer(cache, mesh, MeshSequenceFormat::ObjPlusPc2, "ignored", 7.0f);
    for (int f = 0; f < 4; ++f)
      writer.add(frameOf(mesh, f));
    EXPECT_FALSE(fs::exists(cache));  // appears only at finish()
    writer.finish();
    EXPECT_EQ(writer.frameCount(), 4);
  }
  const PointCache read = readPc2(cache);
  EXPECT_FLOAT_EQ(read.startFrame, 7.0f);
  ASSERT_EQ(read.samples.size(), 4u);
  for (int f = 0; f < 4; ++f)
    EXPECT_EQ(read.samples[static_cast<std::size_t>(f)], frameOf(mesh, f).cast<float>()) << "frame " << f;
  EXPECT_EQ(MeshSequenceWriter::restObjPath(cache), dir.file("anim.obj"));
  const Mesh rest = readObj(dir.file("anim.obj"));
  EXPECT_EQ(rest.vertices, mesh.vertices);
  EXPECT_EQ(test::entryCount(dir.path()), 2u);
}

TEST(MeshSequenceWriter, ObjAndPlySequencesNumberTheirFramesFromOne)
{
  test::TempDir dir;
  const Mesh mesh = triangle();
  {
    MeshSequenceWriter obj(dir.file("objs"), mesh, MeshSequenceFormat::ObjSequence, "face", 0.0f);
    MeshSequenceWriter ply(dir.file("plys"), mesh, MeshSequenceFormat::PlySequence, "face", 0.0f);
    for (int f = 0; f < 3; ++f) {
      obj.add(frameOf(mesh, f));
      ply.add(frameOf(mesh, f));
    }
    obj.finish();
    ply.finish();
  }
  for (int f = 0; f < 3; ++f) {
    const std::string number = "_000" + std::to_string(f + 1);
    EXPECT_EQ(readObj(dir.file("objs/face" + number + ".obj")).vertices, frameOf(mesh, f));
    EXPECT_EQ(readPly(dir.file("plys/face" + number + ".ply")).vertices, frameOf(mesh, f));
  }
  EXPECT_EQ(test::entryCount(dir.file("objs")), 3u);
  EXPECT_EQ(readObj(dir.file("plys/face_neutral.obj")).vertices, mesh.vertices);
  EXPECT_EQ(test::entryCount(dir.file("plys")), 4u);
}

TEST(MeshSequenceWriter, AnUnfinishedCacheLeavesNoFileAtAll)
{
  test::TempDir dir;
  const Mesh mesh = triangle();
  {
    MeshSequenceWriter writer(dir.file("anim.pc2"), mesh, MeshSequenceFormat::ObjPlusPc2, "x", 0.0f);
    writer.add(frameOf(mesh, 1));
    writer.add(frameOf(mesh, 2));
  }  // cancelled: destroyed without finish()
  EXPECT_EQ(test::entryCount(dir.path()), 0u);  // no cache, no OBJ, no temporary file
}

TEST(MeshSequenceWriter, AnUnfinishedSequenceRemovesItsFramesButNothingElse)
{
  test::TempDir dir;
  const Mesh mesh = triangle();
  {
    MeshSequenceWriter writer(dir.file("new/folder"), mesh, MeshSequenceFormat::PlySequence, "face", 0.0f);
    writer.add(frameOf(mesh, 1));
    EXPECT_TRUE(fs::exists(dir.file("new/folder/face_0001.ply")));
  }
  EXPECT_FALSE(fs::exists(dir.file("new/folder")));  // the folder it created goes too

  writeFileAtomically(dir.file("keep.txt"), "not ours");
  {
    MeshSequenceWriter writer(dir.path(), mesh, MeshSequenceFormat::ObjSequence, "face", 0.0f);
    writer.add(frameOf(mesh, 1));
    writer.add(frameOf(mesh, 2));
    EXPECT_THROW(writer.add(MeshVertices::Zero(2, 3)), InvalidArgument);
  }
  EXPECT_TRUE(fs::exists(dir.file("keep.txt")));
  EXPECT_TRUE(fs::exists(dir.file("new")));  // a folder it did not create stays
  EXPECT_EQ(test::entryCount(dir.path()), 2u);
}

TEST(MeshSequenceWriter, AFolderThatCannotBeCreatedIsAClearError)
{
  test::TempDir dir;
  writeFileAtomically(dir.file("file"), "x");
  try {
    MeshSequenceWriter writer(dir.file("file/sub"), triangle(), MeshSequenceFormat::ObjSequence, "face", 0.0f);
    FAIL() << "expected IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("file/sub"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace mocap
