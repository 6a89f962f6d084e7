// BlendshapeRig (sparse shapes, evaluation, checks) and readObjRig (ICT FaceKit's layout).
#include "face_mesh_fixture.h"

#include "mocap/base/error.h"
#include "mocap/io/obj_rig_reader.h"
#include "mocap/model/blendshape_rig.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

namespace mocap {
namespace {

MeshVertices lifted(const Mesh& mesh, std::initializer_list<Eigen::Index> vertices, double by)
{
  MeshVertices v = mesh.vertices;
  for (const Eigen::Index i : vertices)
    v(i, 1) += by;
  return v;
}

TEST(BlendshapeRig, StoresOnlyMovedVerticesAndEvaluatesTheBlend)
{
  const Mesh& face = test::mediaPipeFace();
  BlendshapeRig rig;
  rig.neutral = face;
  rig.shapes.push_back(sparseShape("up", face.vertices, lifted(face, {3, 10}, 1.0), 1e-9));
  rig.shapes.push_back(sparseShape("down", face.vertices, lifted(face, {10, 20}, -2.0), 1e-9));
  EXPECT_EQ(rig.shapes[0].vertices, (std::vector<Eigen::Index>{3, 10}));
  EXPECT_EQ(rig.shapes[1].deltaOf(20), Eigen::Vector3d(0.0, -2.0, 0.0));
  EXPECT_EQ(rig.shapes[1].deltaOf(3), Eigen::Vector3d::Zero());
  MeshVertices out;
  rig.evaluate(Eigen::Vector2d(0.5, 0.25), out);
  EXPECT_DOUBLE_EQ(out(10, 1), face.vertices(10, 1) + 0.5 - 0.5);
  EXPECT_DOUBLE_EQ(out(3, 1), face.vertices(3, 1) + 0.5);
  EXPECT_DOUBLE_EQ(out(20, 1), face.vertices(20, 1) - 0.5);
  EXPECT_EQ(out.row(100), face.vertices.row(100));
  EXPECT_THROW(rig.evaluate(Eigen::Vector3d::Zero(), out), InvalidArgument);
  EXPECT_EQ(rig.shapeIndex("down"), 1);
  EXPECT_FALSE(rig.shapeIndex("sideways"));
  EXPECT_EQ(selectShapes(rig, {"down"}).shapeNames(), std::vector<std::string>{"down"});
  EXPECT_THROW((void)selectShapes(rig, {"down", "down"}), InvalidArgument);
  EXPECT_THROW((void)selectShapes(rig, {"sideways"}), InvalidArgument);
}

TEST(BlendshapeRig, RejectsMismatchedAndNonFiniteShapes)
{
  const Mesh& face = test::mediaPipeFace();
  EXPECT_THROW((void)sparseShape("short", face.vertices, face.vertices.topRows(10), 1e-9), InvalidArgument);
  MeshVertices bad = face.vertices;
  bad(5, 2) = std::nan("");
  EXPECT_THROW((void)sparseShape("nan", face.vertices, bad, 1e-9), InvalidArgument);
  BlendshapeRig rig;
  rig.neutral = face;
  EXPECT_THROW(checkRig(rig), InvalidArgument);  // no shapes
  rig.shapes.push_back(sparseShape("a", face.vertices, lifted(face, {1}, 1.0), 1e-9));
  rig.shapes.push_back(rig.shapes[0]);
  EXPECT_THROW(checkRig(rig), InvalidArgument);  // two called "a"
  rig.shapes[1].name = "b";
  EXPECT_NO_THROW(checkRig(rig));
  rig.shapes[1].vertices[0] = face.vertexCount();
  EXPECT_THROW(checkRig(rig), InvalidArgument);
}

TEST(ObjRigReader, ReadsANeutralAndAFolderOfShapesInNameOrder)
{
  const test::TempDir dir;
  const Mesh& face = test::mediaPipeFace();
  writeObj(dir.file("neutral.obj"), face);
  std::filesystem::create_directory(dir.file("shapes"));
  writeObj(dir.path() / "shapes" / "jawOpen.obj", face, lifted(face, {7}, -1.5));
  writeObj(dir.path() / "shapes" / "browUp.obj", face, lifted(face, {1, 2}, 0.5));
  std::ofstream(dir.path() / "shapes" / "README.txt") << "not a shape";
  const BlendshapeRig rig = readObjRig(dir.file("neutral.obj"), dir.file("shapes"));
  EXPECT_EQ(rig.shapeNames(), (std::vector<std::string>{"browUp", "jawOpen"}));
  EXPECT_EQ(rig.shapes[1].vertices, std::vector<Eigen::Index>{7});
  EXPECT_NEAR(rig.shapes[1].deltaOf(7).y(), -1.5, 1e-12);
  const BlendshapeRig only = readObjRig(dir.file("neutral.obj"), dir.file("shapes"), {"jawOpen"});
  EXPECT_EQ(only.shapeNames(), std::vector<std::string>{"jawOpen"});
  EXPECT_THROW((void)readObjRig(dir.file("neutral.obj"), dir.file("shapes"), {"smile"}), InvalidArgument);
}

TEST(ObjRigReader, RefusesAnEmptyFolderAMissingOneAndAShapeOfAnotherMesh)
{
  const test::TempDir dir;
  const Mesh& face = test::mediaPipeFace();
  writeObj(dir.file("neutral.obj"), face);
  std::filesystem::create_directory(dir.file("empty"));
  EXPECT_THROW((void)readObjRig(dir.file("neutral.obj"), dir.file("empty")), IoError);
  EXPECT_THROW((void)readObjRig(dir.file("neutral.obj"), dir.file("absent")), IoError);
  std::filesystem::create_directory(dir.file("shapes"));
  Mesh small;
  small.vertices = face.vertices.topRows(3);
  small.faces.push_back({{0, 1, 2}, {}, {}});
  writeObj(dir.path() / "shapes" / "wrong.obj", small);
  try {
    (void)readObjRig(dir.file("neutral.obj"), dir.file("shapes"));
    FAIL() << "a shape of another mesh was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("wrong.obj"), std::string::npos) << e.what();
  }
}

TEST(BlendshapeRig, RegionKeepsTheVerticesFacesAndShapeEntriesInsideItRenumbered)
{
  const Mesh& face = test::mediaPipeFace();
  BlendshapeRig rig;
  rig.neutral = face;
  rig.shapes.push_back(sparseShape("edge", face.vertices, lifted(face, {99, 100, 250, 300}, 1.0), 1e-9));
  rig.shapes.push_back(sparseShape("outside", face.vertices, lifted(face, {5}, 1.0), 1e-9));
  const BlendshapeRig region = rigRegion(rig, 100, 299);
  ASSERT_EQ(region.neutral.vertexCount(), 200);
  EXPECT_EQ(region.neutral.vertices.row(0), face.vertices.row(100));
  std::size_t inside = 0;
  for (const MeshFace& f : face.faces)
    inside += std::all_of(f.vertices.begin(), f.vertices.end(), [](Eigen::Index v) { return v >= 100 && v <= 299; });
  ASSERT_GT(inside, 0u);
  EXPECT_EQ(region.neutral.faces.size(), inside);
  EXPECT_NO_THROW(checkRig(region));
  EXPECT_EQ(region.shapeNames(), rig.shapeNames());
  EXPECT_EQ(region.shapes[0].vertices, (std::vector<Eigen::Index>{0, 150}));
  EXPECT_EQ(region.shapes[0].deltaOf(150), Eigen::Vector3d(0.0, 1.0, 0.0));
  EXPECT_EQ(region.shapes[1].size(), 0);
  EXPECT_EQ(rigRegion(rig, 0, face.vertexCount() - 1).neutral.faces.size(), face.faces.size());

  EXPECT_THROW((void)rigRegion(rig, 10, 9), InvalidArgument);
  EXPECT_THROW((void)rigRegion(rig, -1, 9), InvalidArgument);
  EXPECT_THROW((void)rigRegion(rig, 0, face.vertexCount()), InvalidArgument);
  EXPECT_THROW((void)rigRegion(rig, 7, 7), InvalidArgument);  // one vertex: no face
}

TEST(BlendshapeRig, PrunedRigDropsEntriesThatMoveNoAxisBeyondTheTolerance)
{
  const Mesh& face = test::mediaPipeFace();
  BlendshapeRig rig;
  rig.neutral = face;
  MeshVertices posed = lifted(face, {4, 8}, 1e-3);
  posed(8, 0) += 0.5;
  posed(12, 2) -= 2e-3;
  rig.shapes.push_back(sparseShape("slight", face.vertices, posed, 0.0));
  ASSERT_EQ(rig.shapes[0].vertices, (std::vector<Eigen::Index>{4, 8, 12}));
  const BlendshapeRig pruned = prunedRig(rig, 1.5e-3);
  EXPECT_EQ(pruned.shapes[0].vertices, (std::vector<Eigen::Index>{8, 12}));
  EXPECT_EQ(pruned.shapes[0].deltaOf(8), rig.shapes[0].deltaOf(8));
  EXPECT_EQ(prunedRig(rig, 0.0).shapes[0].vertices, rig.shapes[0].vertices);
  EXPECT_EQ(pruned.neutral.vertices, face.vertices);
  EXPECT_THROW((void)prunedRig(rig, -1.0), InvalidArgument);
  EXPECT_THROW((void)prunedRig(rig, std::nan("")), InvalidArgument);
}

} // namespace
} // namespace mocap
