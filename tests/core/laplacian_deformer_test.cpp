#include "face_mesh_fixture.h"

#include "mocap/base/error.h"
#include "mocap/deform/laplacian_deformer.h"
#include "mocap/io/obj_io.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <limits>

namespace mocap {
namespace {

using test::mediaPipeFace;

std::vector<MeshPoint> everyNth(Eigen::Index step)
{
  std::vector<MeshPoint> points;
  for (const Eigen::Index v : test::everyNthVertex(0, step))
    points.push_back(MeshPoint::atVertex(v));
  return points;
}

PointSet displacementsOf(const MeshVertices& moved, const std::vector<MeshPoint>& points)
{
  PointSet d(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    d.row(static_cast<Eigen::Index>(i)) = (points[i].on(moved) - points[i].on(mediaPipeFace().vertices)).transpose();
  return d;
}

const LaplacianWeights kWeights[] = {LaplacianWeights::Uniform, LaplacianWeights::Cotangent, LaplacianWeights::MeanValue};

TEST(LaplacianWeights, RowsSumToZeroAndCotangentIsSymmetric)
{
  for (const LaplacianWeights weights : kWeights) {
    const Mesh& face = mediaPipeFace();
    const Eigen::SparseMatrix<double> k = laplacianMatrix(face.vertices, face.triangles(), weights);
    const Eigen::VectorXd rowSums = k * Eigen::VectorXd::Ones(k.cols());
    EXPECT_LT(rowSums.cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().sum() / static_cast<double>(k.rows()))
        << laplacianWeightsName(weights);
    const double asymmetry = Eigen::SparseMatrix<double>(k - Eigen::SparseMatrix<double>(k.transpose())).cwiseAbs().sum();
    if (weights == LaplacianWeights::MeanValue)
      EXPECT_GT(asymmetry, 0.0);  // eq 6 divides by the edge length from vᵢ's side only: not symmetric
    else
      EXPECT_LT(asymmetry, 1e-12 * k.cwiseAbs().sum()) << laplacianWeightsName(weights);
    // Mean-value (eq 6) weights are convex: every off-diagonal entry is ≤ 0.
    if (weights != LaplacianWeights::Cotangent) {
      for (int o = 0; o < k.outerSize(); ++o)
        for (Eigen::SparseMatrix<double>::InnerIterator it(k, o); it; ++it) {
          if (it.row() != it.col()) {
            EXPECT_LE(it.value(), 0.0);
          }
        }
    }
  }
  EXPECT_EQ(countNonManifoldEdges(mediaPipeFace().triangles()), 0);
}

TEST(LaplacianWeights, DegenerateTriangleIsAClearErrorExceptForUniformWeights)
{
  MeshVertices vertices(4, 3);
  vertices << 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0;  // triangle 0-1-2 is a line
  const std::vector<Triangle> triangles = {{0, 1, 3}, {0, 1, 2}};
  for (const LaplacianWeights weights : {LaplacianWeights::Cotangent, LaplacianWeights::MeanValue}) {
    try {
      (void)laplacianMatrix(vertices, triangles, weights);
      ADD_FAILURE() << "degenerate triangle accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find("triangle 1 (vertices 0, 1, 2) is degenerate"), std::string::npos)
          << e.what();
    }
  }
  EXPECT_NO_THROW((void)laplacianMatrix(vertices, triangles, LaplacianWeights::Uniform));
}

TEST(LaplacianWeights, NonManifoldEdgesAreCountedAndSummed)
{
  // Three triangles share edge 0-1 (a fin): documented as summing their terms.
  MeshVertices vertices(5, 3);
  vertices << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.5, 0, 1;
  const std::vector<Triangle> triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  EXPECT_EQ(countNonManifoldEdges(triangles), 1);
  const Eigen::SparseMatrix<double> k = laplacianMatrix(vertices, triangles, LaplacianWeights::Cotangent);
  // Each apex is 1 from the edge's midpoint over a half-base of 0.5: cot = (1 − 0.25)/1, so
  // w₀₁ = 3 · 0.75/2.
  EXPECT_NEAR(k.coeff(0, 1), -1.125, 1e-12);
  const std::vector<MeshPoint> controls = {MeshPoint::atVertex(2), MeshPoint::atVertex(3), MeshPoint::atVertex(4)};
  EXPECT_NO_THROW(LaplacianDeformer(vertices, triangles, controls));
}

TEST(LaplacianDeformer, TranslationIsExactAndSmallRigidMotionWithinTolerance)
{
  const std::vector<MeshPoint> controls = everyNth(12);
  for (const LaplacianWeights weights : kWeights) {
    LaplacianOptions options;
    options.weights = weights;
    options.constraintWeight = 10.0;
    const LaplacianDeformer deformer(mediaPipeFace().vertices, mediaPipeFace().triangles(), controls, options);
    const MeshVertices shifted = mediaPipeFace().vertices.rowwise() + Eigen::RowVector3d(0.5, -1.0, 2.0);
    MeshVertices out;
    deformer.deform(displacementsOf(shifted, controls), out);
    EXPECT_LT((out - shifted).cwiseAbs().maxCoeff(), 1e-5) << laplacianWeightsName(weights);

    // Linear Laplacian editing does not rotate the differential coordinates: a 3° turn is
    // followed only within a tolerance (the free boundary of the open face drifts most): here
    // 25 % of the largest vertex motion at worst and 4 % on average.
    Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
    motion.linear() = Eigen::AngleAxisd(0.05, Eigen::Vector3d(0.1, 1.0, 0.3).normalized()).toRotationMatrix();
    motion.translation() = Eigen::Vector3d(0.2, 0.1, -0.3);
    const MeshVertices moved =
        (mediaPipeFace().vertices * motion.linear().transpose()).rowwise() + motion.translation().transpose();
    deformer.deform(displacementsOf(moved, controls), out);
    const double largest = (moved - mediaPipeFace().vertices).rowwise().norm().maxCoeff();
    EXPECT_LT((out - moved).rowwise().norm().maxCoeff(), 0.25 * largest) << laplacianWeightsName(weights);
    EXPECT_LT((out - moved).rowwise().norm().mean(), 0.04 * largest) << laplacianWeightsName(weights);
  }
}

TEST(LaplacianDeformer, RotationAwareIterationsFollowARotationCloser)
{
  const std::vector<MeshPoint> controls = everyNth(12);
  LaplacianDeformer deformer(mediaPipeFace().vertices, mediaPipeFace().triangles(), controls);
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.1, 1.0, 0.3).normalized()).toRotationMatrix();
  const MeshVertices moved =
      (mediaPipeFace().vertices * motion.linear().transpose()).rowwise() + motion.translation().transpose();
  const PointSet displacements = displacementsOf(moved, controls);
  const std::vector<bool> all(controls.size(), true);
  MeshVertices linear, rotated;
  deformFrame(deformer, displacements, all, 0, linear);
  deformFrame(deformer, displacements, all, 5, rotated);
  const double linearError = (linear - moved).rowwise().norm().mean();
  const double rotatedError = (rotated - moved).rowwise().norm().mean();
  EXPECT_LT(rotatedError, 0.5 * linearError) << linearError << " → " << rotatedError;
  // Zero iterations is the linear solution; a translation stays exact with rotations too.
  EXPECT_EQ(linear, [&] { MeshVertices out; deformer.deform(displacements, out); return out; }());
  const MeshVertices shifted = mediaPipeFace().vertices.rowwise() + Eigen::RowVector3d(0.5, -1.0, 2.0);
  deformer.deformRotationAware(displacementsOf(shifted, controls), all, 3, rotated);
  EXPECT_LT((rotated - shifted).cwiseAbs().maxCoeff(), 1e-5);
  EXPECT_THROW(deformer.deformRotationAware(displacements, all, 101, rotated), InvalidArgument);
}

TEST(LaplacianDeformer, ZeroDisplacementLeavesTheMeshUnchanged)
{
  const std::vector<MeshPoint> controls = everyNth(20);
  const LaplacianDeformer deformer(mediaPipeFace().vertices, mediaPipeFace().triangles(), controls);
  MeshVertices out;
  deformer.deform(PointSet::Zero(static_cast<Eigen::Index>(controls.size()), 3), out);
  EXPECT_EQ(out, mediaPipeFace().vertices);
}

TEST(LaplacianDeformer, PrecomputedResponseEqualsPerFrameBackSubstitution)
{
  std::vector<MeshPoint> controls = everyNth(25);
  controls.push_back(MeshPoint{{10, 11, 12}, Eigen::Vector3d(0.2, 0.5, 0.3)});  // a barycentric control
  for (const LaplacianWeights weights : kWeights) {
    LaplacianOptions options;
    options.weights = weights;
    const LaplacianDeformer deformer(mediaPipeFace().vertices, mediaPipeFace().triangles(), controls, options);
    const PointSet displacements = PointSet::Random(static_cast<Eigen::Index>(controls.size()), 3);
    MeshVertices fast, substituted;
    deformer.deform(displacements, fast);
    deformer.deformBySubstitution(displacements, substituted);
    EXPECT_LT((fast - substituted).cwiseAbs().maxCoeff(), 1e-5) << laplacianWeightsName(weights);
    // Soft constraints: a larger w pulls the controls closer to their targets.
    EXPECT_GT(fast.rowwise().norm().maxCoeff(), 0.0);
  }
}

TEST(LaplacianDeformer, LargerConstraintWeightFollowsControlsMoreClosely)
{
  const std::vector<MeshPoint> controls = everyNth(30);
  const PointSet displacements = PointSet::Random(static_cast<Eigen::Index>(controls.size()), 3);
  double previous = std::numeric_limits<double>::infinity();
  for (const double w : {0.1, 1.0, 10.0}) {
    LaplacianOptions options;
    options.constraintWeight = w;
    const LaplacianDeformer deformer(mediaPipeFace().vertices, mediaPipeFace().triangles(), controls, options);
    MeshVertices out;
    deformer.deform(displacements, out);
    const double miss = (displacementsOf(out, controls) - displacements).norm();
    EXPECT_LT(miss, previous);
    previous = miss;
  }
}

TEST(LaplacianDeformer, MissingControlUsesTheDowndateNotTheStaleSolution)
{
  const std::vector<MeshPoint> controls = everyNth(20);
  const PointSet displacements = PointSet::Random(static_cast<Eigen::Index>(controls.size()), 3);
  LaplacianDeformer deformer(mediaPipeFace().vertices, mediaPipeFace().triangles(), controls);
  std::vector<bool> present(controls.size(), true);
  present[0] = present[7] = false;
  MeshVertices skipped;
  deformer.deform(displacements, present, skipped);

  std::vector<MeshPoint> fewer;
  PointSet fewerDisplacements(static_cast<Eigen::Index>(controls.size()) - 2, 3);
  for (std::size_t c = 0; c < controls.size(); ++c)
    if (present[c]) {
      fewerDisplacements.row(static_cast<Eigen::Index>(fewer.size())) = displacements.row(static_cast<Eigen::Index>(c));
      fewer.push_back(controls[c]);
    }
  const LaplacianDeformer reference(mediaPipeFace().vertices, mediaPipeFace().triangles(), fewer);
  MeshVertices expected;
  reference.deform(fewerDisplacements, expected);
  EXPECT_LT((skipped - expected).cwiseAbs().maxCoeff(), 1e-5);
}

TEST(LaplacianDeformer, ComponentWithoutControlsStaysAtRestAndBadInputIsRejected)
{
  // The face plus a separate triangle far away that no control reaches.
  MeshVertices vertices(mediaPipeFace().vertexCount() + 3, 3);
  vertices << mediaPipeFace().vertices, Eigen::RowVector3d(100, 0, 0), Eigen::RowVector3d(101, 0, 0),
      Eigen::RowVector3d(100, 1, 0);
  std::vector<Triangle> triangles = mediaPipeFace().triangles();
  const Eigen::Index n = mediaPipeFace().vertexCount();
  triangles.push_back({n, n + 1, n + 2});
  const std::vector<MeshPoint> controls = everyNth(20);
  const LaplacianDeformer deformer(vertices, triangles, controls);
  MeshVertices out;
  deformer.deform(PointSet::Ones(static_cast<Eigen::Index>(controls.size()), 3), out);
  EXPECT_EQ(out.bottomRows(3), vertices.bottomRows(3));
  EXPECT_LT((out.topRows(n).rowwise() - Eigen::RowVector3d::Ones() - mediaPipeFace().vertices).cwiseAbs().maxCoeff(),
            1e-5);

  EXPECT_THROW(LaplacianDeformer(vertices, triangles, {}), InvalidArgument);
  EXPECT_THROW(LaplacianDeformer(vertices, triangles, {MeshPoint::atVertex(n + 3)}), InvalidArgument);
  LaplacianOptions bad;
  bad.constraintWeight = 0.0;
  EXPECT_THROW(LaplacianDeformer(vertices, triangles, controls, bad), InvalidArgument);
  // Duplicate controls are soft constraints: accepted, they average their targets.
  std::vector<MeshPoint> duplicated = controls;
  duplicated.push_back(controls.front());
  EXPECT_NO_THROW(LaplacianDeformer(vertices, triangles, duplicated));
}

} // namespace
} // namespace mocap
