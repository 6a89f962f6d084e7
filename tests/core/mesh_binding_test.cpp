#include "face_mesh_fixture.h"

#include "mocap/evaluation/deformation_evaluation.h"
#include "mocap/base/error.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/io/obj_io.h"
#include "mocap/deform/rbf_deformer.h"
#include "mocap/deform/retarget.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace mocap {
namespace {

using test::mediaPipeFace;

// The take's view of mesh points: mm, Z up, facing −Y, offset — the mesh→take similarity inverted.
Similarity turnedMeshToTake()
{
  Similarity t;
  t.scale = 10.0;  // cm → mm
  t.rotation = Eigen::AngleAxisd(0.5 * std::acos(-1.0), Eigen::Vector3d::UnitX()).toRotationMatrix() *
               Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  t.translation = Eigen::Vector3d(20.0, -250.0, 1050.0);
  return t;
}

std::vector<Eigen::Index> markerVertices()
{
  return test::everyNthVertex(3, 16);
}

std::vector<std::string> labelsFor(std::size_t count)
{
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < count; ++i)
    labels.push_back("m" + std::to_string(i));
  return labels;
}

TEST(MeshBinding, ClosestTriangleWeightsCoverFaceEdgeAndVertexRegions)
{
  const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  EXPECT_TRUE(closestTriangleWeights({0.5, 0.5, 3}, a, b, c).isApprox(Eigen::Vector3d(0.5, 0.25, 0.25)));
  EXPECT_TRUE(closestTriangleWeights({-1, -1, 0}, a, b, c).isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(closestTriangleWeights({1, -3, 1}, a, b, c).isApprox(Eigen::Vector3d(0.5, 0.5, 0)));
  EXPECT_TRUE(closestTriangleWeights({3, 3, 0}, a, b, c).isApprox(Eigen::Vector3d(0, 0.5, 0.5)));
  // Degenerate (all corners equal): the vertex.
  EXPECT_TRUE(closestTriangleWeights({1, 1, 1}, a, a, a).isApprox(Eigen::Vector3d(1, 0, 0)));
}

TEST(MeshBinding, SimilarityFitRecoversScaleRotationAndTranslation)
{
  const Similarity truth = turnedMeshToTake();
  const PointSet from = mediaPipeFace().vertices(markerVertices(), Eigen::all);
  const Similarity fit = fitSimilarity(from, truth.applyToRows(from));
  EXPECT_NEAR(fit.scale, 10.0, 1e-9);
  EXPECT_TRUE(fit.rotation.isApprox(truth.rotation, 1e-9));
  EXPECT_TRUE(fit.translation.isApprox(truth.translation, 1e-9));
  EXPECT_THROW((void)fitSimilarity(from.topRows(2), from.topRows(2)), InvalidArgument);
  EXPECT_THROW((void)fitSimilarity(PointSet::Ones(4, 3), from.topRows(4)), InvalidArgument);
}

TEST(MeshBinding, PairsAndIcpBothBindMarkersOnMeshVerticesBack)
{
  const std::vector<Eigen::Index> vertices = markerVertices();
  const PointSet markers = turnedMeshToTake().applyToRows(mediaPipeFace().vertices(vertices, Eigen::all));
  const std::vector<std::string> labels = labelsFor(vertices.size());
  AutoBindOptions withPairs;
  withPairs.pairs = {{0, vertices[0]}, {10, vertices[10]}, {20, vertices[20]}};
  AutoBindOptions icp;
  for (const AutoBindOptions& options : {withPairs, icp}) {
    const MeshBinding binding = autoBind(mediaPipeFace(), labels, markers, options);
    ASSERT_EQ(binding.markers.size(), vertices.size());
    EXPECT_NEAR(binding.alignment.scale, 0.1, 1e-3);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      EXPECT_LT(binding.markers[i].residual, 0.05) << labels[i];
      const MeshVertices& face = mediaPipeFace().vertices;
      EXPECT_LT((binding.markers[i].point.on(face) - face.row(vertices[i]).transpose()).norm(), 1e-3) << labels[i];
    }
  }
  AutoBindOptions twoPairs;
  twoPairs.pairs = {{0, 1}, {1, 2}};
  EXPECT_THROW((void)autoBind(mediaPipeFace(), labels, markers, twoPairs), InvalidArgument);
  AutoBindOptions outside;
  outside.pairs = {{0, 1}, {1, 2}, {2, 100000}};
  EXPECT_THROW((void)autoBind(mediaPipeFace(), labels, markers, outside), InvalidArgument);
}

TEST(MeshBinding, JsonRoundTripAndClearErrorsForBindingsOffTheMesh)
{
  MeshBinding binding;
  binding.meshVertices = mediaPipeFace().vertexCount();
  binding.markers.push_back({"a", MeshPoint::atVertex(5), 0.25});
  binding.markers.push_back({"b", MeshPoint{{1, 2, 3}, Eigen::Vector3d(0.2, 0.3, 0.5)}, 1.5});
  binding.alignment = turnedMeshToTake();
  binding.hasAlignment = true;
  const MeshBinding back = parseBinding(bindingJson(binding), "b.json", mediaPipeFace().vertexCount());
  ASSERT_EQ(back.markers.size(), 2u);
  EXPECT_EQ(back.markers[0].point.vertices, binding.markers[0].point.vertices);
  EXPECT_TRUE(back.markers[0].point.isVertex());
  EXPECT_EQ(back.markers[1].point.vertices, binding.markers[1].point.vertices);
  EXPECT_EQ(back.markers[1].point.weights, binding.markers[1].point.weights);
  EXPECT_EQ(back.markers[1].residual, 1.5);
  EXPECT_TRUE(back.alignment.rotation.isApprox(binding.alignment.rotation, 0.0));
  // The plain form: label → vertex index.
  EXPECT_EQ(parseBinding(R"({"markers": {"x": 7}})", "p.json", 468).markers[0].point.vertices[0], 7);

  const std::pair<const char*, const char*> cases[] = {
      {R"({"markers": {"x": 468}})", "bound off the mesh"},
      {R"({"markers": {"x": -1}})", "bound off the mesh"},
      {R"({"markers": {"x": {"triangle": [1, 2, 3], "weights": [0.5, 0.6, -0.1]}}})", "bound off the mesh"},
      {R"({"markers": {"x": 1, "x": 2}})", "repeated key \"x\""},
      {R"({"mesh_vertices": 26719, "markers": {"x": 1}})", "26719 vertices"},
      {R"({"markers": []})", "\"markers\" object"},
      {R"({"markers": {}})", "no markers"},
      {R"({"markers": {"x": 1})", "unexpected end of JSON"},
      {R"({"markers": {"x": "nose"}})", "vertex index or an object"},
  };
  for (const auto& [text, message] : cases) {
    try {
      (void)parseBinding(text, "bad.json", 468);
      ADD_FAILURE() << "accepted " << text;
    } catch (const FormatError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

TEST(MeshBinding, LeaveOutErrorIsSmallForMotionTheControlsSpan)
{
  // A take whose markers sit on mesh vertices and follow a smooth (affine) motion of the face:
  // the hidden markers' bound points follow it too, so the leave-out error is ~0 for RBF with the
  // affine term, and a mesh at rest would miss by the full motion.
  const std::vector<Eigen::Index> vertices = markerVertices();
  const std::vector<std::string> labels = labelsFor(vertices.size());
  Take take(labels, 20, 100.0);
  take.valid().setConstant(true);
  const Similarity toTake = turnedMeshToTake();
  for (Eigen::Index f = 0; f < 20; ++f) {
    Eigen::Matrix3d stretch = Eigen::Matrix3d::Identity();
    stretch(1, 1) += 0.01 * static_cast<double>(f);  // a growing vertical stretch of the face
    for (std::size_t m = 0; m < vertices.size(); ++m) {
      const Eigen::Vector3d p = stretch * mediaPipeFace().vertices.row(vertices[m]).transpose();
      take.setPosition(f, static_cast<Eigen::Index>(m), toTake.apply(p));
    }
  }
  take.valid()(5, 3) = false;  // a missing marker in a frame is skipped
  std::vector<Eigen::Index> markers(vertices.size());
  std::vector<MeshPoint> points;
  for (std::size_t m = 0; m < vertices.size(); ++m) {
    markers[m] = static_cast<Eigen::Index>(m);
    points.push_back(MeshPoint::atVertex(vertices[m]));
  }
  const Retarget retarget =
      fitRetarget(markerPositions(take, 0, markers), mediaPipeFace().vertices(vertices, Eigen::all),
                  RetargetScale::Uniform);
  EXPECT_NEAR(retarget.uniformScale, 0.1, 1e-9);
  const DeformerFactory factory = [](const std::vector<MeshPoint>& controls) -> std::unique_ptr<MeshDeformer> {
    return std::make_unique<RbfDeformer>(mediaPipeFace().vertices, boundPositions(mediaPipeFace().vertices, controls));
  };
  const LeaveOutResult result = evaluateLeaveOut(take, markers, points, 0, retarget, mediaPipeFace().vertices, factory);
  EXPECT_EQ(result.hidden.size(), static_cast<std::size_t>(std::lround(0.2 * static_cast<double>(vertices.size()))));
  EXPECT_GT(result.samples, 0);
  EXPECT_LT(result.meanError, 1e-4);
  EXPECT_GT(result.restError, 0.5);
  // Per-axis scale of a uniformly scaled set is the uniform scale.
  const Retarget perAxis =
      fitRetarget(markerPositions(take, 0, markers), mediaPipeFace().vertices(vertices, Eigen::all),
                  RetargetScale::PerAxis);
  EXPECT_TRUE(perAxis.axisScale.isApprox(Eigen::Vector3d::Constant(0.1), 1e-9));
  LeaveOutOptions bad;
  bad.fraction = 1.0;
  EXPECT_THROW((void)evaluateLeaveOut(take, markers, points, 0, retarget, mediaPipeFace().vertices, factory, bad),
               InvalidArgument);
}

} // namespace
} // namespace mocap
