// FaceRig: the per-take set-up shared by `mocap deform` and the studio's face mesh panel.
#include "face_mesh_fixture.h"

#include "mocap/base/error.h"
#include "mocap/deform/face_rig.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace mocap {
namespace {

using test::mediaPipeFace;

// The take sees the mesh in mm (×10), rotated and offset.
Similarity uprightMeshToTake()
{
  Similarity t;
  t.scale = 10.0;
  t.rotation = Eigen::AngleAxisd(0.5 * std::acos(-1.0), Eigen::Vector3d::UnitX()).toRotationMatrix();
  t.translation = Eigen::Vector3d(20.0, -250.0, 1050.0);
  return t;
}

struct Rigged
{
  Take take;
  MeshBinding binding;
  std::vector<Eigen::Index> vertices;
};

// Markers on every 24th vertex; frame 0 is the rest pose, frame 1 moves marker 3 by `lift` mm
// along the take's z, frame 2 moves every marker by `shift` mm, frame 3 has marker 3 missing.
Rigged rigged(const Eigen::Vector3d& lift, const Eigen::Vector3d& shift)
{
  Rigged r;
  r.vertices = test::everyNthVertex(5, 24);
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < r.vertices.size(); ++i) {
    labels.push_back("m" + std::to_string(i));
    r.binding.markers.push_back({labels.back(), MeshPoint::atVertex(r.vertices[i]), 0.0});
  }
  r.binding.meshVertices = mediaPipeFace().vertexCount();
  r.take = Take(labels, 4, 100.0);
  for (std::size_t i = 0; i < r.vertices.size(); ++i) {
    const auto m = static_cast<Eigen::Index>(i);
    const Eigen::Vector3d p = uprightMeshToTake().apply(mediaPipeFace().vertices.row(r.vertices[i]).transpose());
    for (Eigen::Index f = 0; f < 4; ++f) {
      r.take.setPosition(f, m, p + (f == 1 && m == 3 ? lift : Eigen::Vector3d::Zero()) +
                                   (f == 2 ? shift : Eigen::Vector3d::Zero()));
      r.take.valid()(f, m) = !(f == 3 && m == 3);
    }
  }
  return r;
}

TEST(FaceRig, BoundVerticesFollowTheRetargetedMarkersAndAShiftMovesTheWholeMesh)
{
  const Eigen::Vector3d lift(0, 0, 5), shift(3, -2, 1);
  Rigged r = rigged(lift, shift);
  FaceRig rig(mediaPipeFace(), r.binding, r.take);
  EXPECT_EQ(rig.neutralFrame(), 0);
  EXPECT_NEAR(rig.retarget().uniformScale, 0.1, 1e-9);
  EXPECT_GE(rig.setupSeconds(), 0.0);
  // The placement takes the neutral markers onto their bound vertices.
  for (std::size_t i = 0; i < r.vertices.size(); ++i)
    EXPECT_LT((rig.placement().apply(r.take.position(0, static_cast<Eigen::Index>(i))) -
               mediaPipeFace().vertices.row(r.vertices[i]).transpose())
                  .norm(),
              1e-9);
  MeshVertices out;
  EXPECT_TRUE(rig.deform(r.take, 0, out));
  EXPECT_LT((out - mediaPipeFace().vertices).cwiseAbs().maxCoeff(), 1e-5);

  ASSERT_TRUE(rig.deform(r.take, 1, out));
  // The lift in mesh axes and units (cm).
  const Eigen::Vector3d expected = uprightMeshToTake().rotation.transpose() * lift * 0.1;
  const Eigen::Vector3d moved = (out.row(r.vertices[3]) - mediaPipeFace().vertices.row(r.vertices[3])).transpose();
  EXPECT_LT((moved - expected).norm(), 1e-5) << moved.transpose();
  for (std::size_t i = 0; i < r.vertices.size(); ++i) {
    if (i != 3) {  // an RBF interpolates: the other controls stay put
      EXPECT_LT((out.row(r.vertices[i]) - mediaPipeFace().vertices.row(r.vertices[i])).norm(), 1e-5) << i;
    }
  }

  ASSERT_TRUE(rig.deform(r.take, 2, out));  // the affine term reproduces a translation everywhere
  const Eigen::RowVector3d step = (uprightMeshToTake().rotation.transpose() * shift * 0.1).transpose();
  EXPECT_LT(((out - mediaPipeFace().vertices).rowwise() - step).cwiseAbs().maxCoeff(), 1e-5);
}

TEST(FaceRig, LaplacianFollowsTheMarkersApproximatelyAndMissingMarkersAreReported)
{
  const Eigen::Vector3d lift(0, 0, 5);
  Rigged r = rigged(lift, Eigen::Vector3d::Zero());
  FaceRigOptions options;
  options.method = DeformMethod::Laplacian;
  options.laplacian.constraintWeight = 10.0;
  FaceRig rig(mediaPipeFace(), r.binding, r.take, options);
  MeshVertices out;
  ASSERT_TRUE(rig.deform(r.take, 1, out));
  const Eigen::Vector3d expected = uprightMeshToTake().rotation.transpose() * lift * 0.1;
  const Eigen::Vector3d moved = (out.row(r.vertices[3]) - mediaPipeFace().vertices.row(r.vertices[3])).transpose();
  EXPECT_GT(moved.dot(expected.normalized()), 0.8 * expected.norm()) << moved.transpose();
  EXPECT_LT((moved - expected).norm(), 0.2 * expected.norm());
  // Frame 3 misses marker 3 and is otherwise at rest: the mesh stays at rest.
  EXPECT_FALSE(rig.deform(r.take, 3, out));
  EXPECT_LT((out - mediaPipeFace().vertices).cwiseAbs().maxCoeff(), 1e-5);
  // The factory makes the same deformer kind for a subset (leave-out evaluation).
  const std::vector<MeshPoint> some(rig.points().begin(), rig.points().begin() + 5);
  EXPECT_EQ(rig.factory()(some)->controlCount(), 5);
}

TEST(FaceRig, ClearErrorsForLabelsNotInTheTakeBadOptionsAndFramesOutside)
{
  Rigged r = rigged(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  MeshBinding missing = r.binding;
  missing.markers.push_back({"nose_tip", MeshPoint::atVertex(1), 0.0});
  EXPECT_THROW(FaceRig(mediaPipeFace(), missing, r.take), InvalidArgument);
  FaceRigOptions rotations;
  rotations.rotations = 2;  // RBF has no rotation-aware variant
  EXPECT_THROW(FaceRig(mediaPipeFace(), r.binding, r.take, rotations), InvalidArgument);
  MeshBinding coincident = r.binding;
  coincident.markers[1].point = coincident.markers[0].point;
  EXPECT_THROW(FaceRig(mediaPipeFace(), coincident, r.take), InvalidArgument);
  FaceRigOptions neutral;
  neutral.neutralFrame = r.take.firstFrame() + 3;  // marker 3 is missing there (take numbering)
  EXPECT_THROW(FaceRig(mediaPipeFace(), r.binding, r.take, neutral), InvalidArgument);
  MeshBinding otherMesh = r.binding;
  otherMesh.meshVertices = 26719;
  EXPECT_THROW(FaceRig(mediaPipeFace(), otherMesh, r.take), InvalidArgument);

  FaceRig rig(mediaPipeFace(), r.binding, r.take);
  MeshVertices out;
  EXPECT_THROW(rig.deform(r.take, 4, out), InvalidArgument);
  EXPECT_THROW(rig.deform(r.take, -1, out), InvalidArgument);
  Take fewer = r.take;
  (void)fewer.removeMarker(fewer.markerCount() - 1);
  EXPECT_THROW(rig.deform(fewer, 0, out), InvalidArgument);
}

TEST(FaceRig, MethodNamesRoundTrip)
{
  for (const DeformMethod method : {DeformMethod::Rbf, DeformMethod::Laplacian})
    EXPECT_EQ(parseDeformMethod(deformMethodName(method)), method);
  EXPECT_FALSE(parseDeformMethod("linear"));
}

} // namespace
} // namespace mocap
