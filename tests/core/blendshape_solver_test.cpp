// BlendshapeSolver: takes to the weights of a blendshape rig (bvls, ridge with GCV, temporal).
#include "face_mesh_fixture.h"

#include "mocap/base/error.h"
#include "mocap/base/random.h"
#include "mocap/deform/blendshape_solver.h"
#include "mocap/evaluation/deformation_evaluation.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

namespace mocap {
namespace {

const double kPi = std::acos(-1.0);

// Eight smooth bumps on the MediaPipe face (cm), overlapping so the shapes are correlated as a
// real rig's are; each moves only the vertices near its centre (sparse).
const BlendshapeRig& bumpRig()
{
  static const BlendshapeRig rig = [] {
    BlendshapeRig r;
    r.neutral = test::mediaPipeFace();
    Random random(7);
    for (int s = 0; s < 8; ++s) {
      const Eigen::Index centreVertex = static_cast<Eigen::Index>(random.uniform() * 468.0);
      const Eigen::Vector3d centre = r.neutral.vertices.row(centreVertex).transpose();
      const Eigen::Vector3d direction = Eigen::Vector3d(random.normal(), random.normal(), random.normal()).normalized();
      MeshVertices posed = r.neutral.vertices;
      for (Eigen::Index v = 0; v < posed.rows(); ++v) {
        const double falloff = std::exp(-(posed.row(v).transpose() - centre).squaredNorm() / 16.0);
        if (falloff > 1e-3)
          posed.row(v) += 0.8 * falloff * direction.transpose();
      }
      r.shapes.push_back(sparseShape("shape" + std::to_string(s), r.neutral.vertices, posed, 1e-12));
    }
    return r;
  }();
  return rig;
}

// The take sees the mesh in mm (×10), rotated and offset.
Similarity obliqueMeshToTake()
{
  Similarity t;
  t.scale = 10.0;
  t.rotation = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1.0, 0.5, 0.0).normalized()).toRotationMatrix();
  t.translation = Eigen::Vector3d(20.0, -250.0, 1050.0);
  return t;
}

// Known weights: smooth, 0 at frame 0 (the neutral), touching both bounds.
Eigen::MatrixXd knownWeights(Eigen::Index frames, Eigen::Index shapes)
{
  Eigen::MatrixXd w(frames, shapes);
  for (Eigen::Index f = 0; f < frames; ++f)
    for (Eigen::Index s = 0; s < shapes; ++s) {
      const double phase = 2.0 * kPi * static_cast<double>(f) / (60.0 + 13.0 * static_cast<double>(s));
      w(f, s) = std::clamp(1.2 * 0.5 * (1.0 - std::cos(phase)) - 0.1, 0.0, 1.0);
    }
  w.row(0).setZero();
  return w;
}

struct Synthetic
{
  Take take;
  MeshBinding binding;
  Eigen::MatrixXd weights;
};

// Markers on every 12th vertex, posed by the known weights, seen through meshToTake, plus
// Gaussian noise of `noise` mm per coordinate (none on the neutral frame).
Synthetic synthetic(double noise, Eigen::Index frames = 300)
{
  Synthetic s;
  const BlendshapeRig& rig = bumpRig();
  s.weights = knownWeights(frames, rig.shapeCount());
  const std::vector<Eigen::Index> vertices = test::everyNthVertex(3, 12);
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    labels.push_back("m" + std::to_string(i));
    s.binding.markers.push_back({labels.back(), MeshPoint::atVertex(vertices[i]), 0.0});
  }
  s.binding.meshVertices = rig.neutral.vertexCount();
  s.take = Take(labels, frames, 100.0);
  Random random(11);
  MeshVertices posed;
  for (Eigen::Index f = 0; f < frames; ++f) {
    rig.evaluate(s.weights.row(f).transpose(), posed);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      Eigen::Vector3d p = obliqueMeshToTake().apply(posed.row(vertices[i]).transpose());
      if (f > 0)
        p += noise * Eigen::Vector3d(random.normal(), random.normal(), random.normal());
      s.take.setPosition(f, static_cast<Eigen::Index>(i), p);
      s.take.valid()(f, static_cast<Eigen::Index>(i)) = true;
    }
  }
  return s;
}

double rmsError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b)
{
  return std::sqrt((a - b).squaredNorm() / static_cast<double>(a.size()));
}

BlendshapeSolveResult solveWith(const Synthetic& s, BlendshapeSolveMethod method, BlendshapeSolveOptions options = {})
{
  options.method = method;
  return BlendshapeSolver(bumpRig(), s.binding, s.take, options).solve(s.take);
}

TEST(BlendshapeSolver, RecoversExactWeightsPerFrame)
{
  const Synthetic s = synthetic(0.0);
  for (const auto method : {BlendshapeSolveMethod::Bvls, BlendshapeSolveMethod::Ridge}) {
    BlendshapeSolveOptions options;
    options.lambda = 0.0;
    const BlendshapeSolveResult r = solveWith(s, method, options);
    EXPECT_LT((r.weights - s.weights).cwiseAbs().maxCoeff(), 1e-6) << blendshapeSolveMethodName(method);
    EXPECT_LT(r.residual.maxCoeff(), 1e-6);
    EXPECT_GE(r.weights.minCoeff(), 0.0);
    EXPECT_LE(r.weights.maxCoeff(), 1.0);
  }
}

TEST(BlendshapeSolver, TemporalWithoutPriorsConvergesToTheBoundedSolution)
{
  const Synthetic s = synthetic(0.0);
  BlendshapeSolveOptions options;
  options.lambda = 0.0;
  options.smoothness = 0.0;
  const BlendshapeSolveResult r = solveWith(s, BlendshapeSolveMethod::Temporal, options);
  EXPECT_LT((r.weights - s.weights).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_GT(r.iterations, 1);
}

TEST(BlendshapeSolver, TemporalDefaultBeatsPerFrameBvlsOnNoisyMarkers)
{
  const Synthetic s = synthetic(0.5);
  const double bvls = rmsError(solveWith(s, BlendshapeSolveMethod::Bvls).weights, s.weights);
  const BlendshapeSolveResult temporal = solveWith(s, BlendshapeSolveMethod::Temporal);
  const double ridge = rmsError(solveWith(s, BlendshapeSolveMethod::Ridge).weights, s.weights);
  EXPECT_LT(rmsError(temporal.weights, s.weights), 0.6 * bvls) << "bvls " << bvls << " ridge " << ridge;
  EXPECT_TRUE(temporal.lambdaChosen);
}

TEST(BlendshapeSolver, GcvChoosesMoreRegularisationForNoisierMarkers)
{
  const Synthetic clean = synthetic(0.0), noisy = synthetic(2.0);
  const double cleanLambda = solveWith(clean, BlendshapeSolveMethod::Ridge).lambda;
  const double noisyLambda = solveWith(noisy, BlendshapeSolveMethod::Ridge).lambda;
  EXPECT_LE(cleanLambda, 1e-6);
  EXPECT_GT(noisyLambda, 10.0 * cleanLambda);
}

TEST(BlendshapeSolver, DropsMissingMarkersAndHoldsFramesWithTooFew)
{
  Synthetic s = synthetic(0.0, 200);
  for (Eigen::Index f = 50; f < 60; ++f)
    for (Eigen::Index m = 0; m < 4; ++m)
      s.take.valid()(f, m) = false;
  for (Eigen::Index f = 100; f < 103; ++f)
    s.take.valid().row(f).setConstant(false);
  for (const auto method : {BlendshapeSolveMethod::Bvls, BlendshapeSolveMethod::Temporal}) {
    BlendshapeSolveOptions options;
    options.lambda = 0.0;
    options.smoothness = 0.0;
    const BlendshapeSolveResult r = solveWith(s, method, options);
    const double tolerance = method == BlendshapeSolveMethod::Bvls ? 1e-6 : 1e-3;
    EXPECT_LT((r.weights.middleRows(50, 10) - s.weights.middleRows(50, 10)).cwiseAbs().maxCoeff(), tolerance);
    for (Eigen::Index f = 0; f < 200; ++f)
      EXPECT_EQ(r.held[static_cast<std::size_t>(f)], f >= 100 && f < 103) << f;
    for (Eigen::Index f = 100; f < 103; ++f) {
      EXPECT_EQ(r.weights.row(f), r.weights.row(99));
      EXPECT_TRUE(std::isnan(r.residual(f)));
    }
  }
}

TEST(BlendshapeSolver, SparsityPullsUnusedShapesToZero)
{
  Synthetic s = synthetic(0.3);
  BlendshapeSolveOptions options;
  options.sparsity = 0.0;
  const Eigen::MatrixXd without = solveWith(s, BlendshapeSolveMethod::Bvls, options).weights;
  options.sparsity = 0.05;
  const Eigen::MatrixXd with = solveWith(s, BlendshapeSolveMethod::Bvls, options).weights;
  EXPECT_LT(with.sum(), without.sum());
  EXPECT_GT((with.array() == 0.0).count(), (without.array() == 0.0).count());
}

TEST(BlendshapeSolver, LeaveOutErrorIsSmallOnAnExactRigAndGrowsWithNoise)
{
  const Synthetic clean = synthetic(0.0), noisy = synthetic(1.0);
  BlendshapeSolveOptions options;
  options.method = BlendshapeSolveMethod::Bvls;
  const LeaveOutResult exact = evaluateBlendshapeLeaveOut(BlendshapeSolver(bumpRig(), clean.binding, clean.take, options), clean.take);
  const LeaveOutResult rough = evaluateBlendshapeLeaveOut(BlendshapeSolver(bumpRig(), noisy.binding, noisy.take, options), noisy.take);
  EXPECT_GT(exact.samples, 0);
  EXPECT_LT(exact.meanError, 1e-3 * exact.restError);
  EXPECT_GT(rough.meanError, 10.0 * exact.meanError);
  EXPECT_GT(exact.restError, 1.0);  // the hidden markers moved millimetres
}

TEST(BlendshapeSolver, RejectsBadInput)
{
  const Synthetic s = synthetic(0.0, 10);
  BlendshapeSolveOptions options;
  options.lambda = -1.0;
  EXPECT_THROW(BlendshapeSolver(bumpRig(), s.binding, s.take, options), InvalidArgument);
  options = {};
  options.minimumMarkerShare = 1.5;
  EXPECT_THROW(BlendshapeSolver(bumpRig(), s.binding, s.take, options), InvalidArgument);
  BlendshapeRig twice = bumpRig();
  twice.shapes[1].name = twice.shapes[0].name;
  EXPECT_THROW(BlendshapeSolver(twice, s.binding, s.take), InvalidArgument);
  BlendshapeRig none = bumpRig();
  none.shapes.clear();
  EXPECT_THROW(BlendshapeSolver(none, s.binding, s.take), InvalidArgument);
  MeshBinding other = s.binding;
  other.meshVertices = 10;
  EXPECT_THROW(BlendshapeSolver(bumpRig(), other, s.take), InvalidArgument);
  const BlendshapeSolver solver(bumpRig(), s.binding, s.take);
  EXPECT_THROW((void)solver.solve(s.take, std::vector<bool>(3, true)), InvalidArgument);
  EXPECT_THROW((void)solver.solve(s.take, std::vector<bool>(s.binding.markers.size(), false)), InvalidArgument);
}

TEST(BlendshapeSolver, MethodNamesRoundTrip)
{
  for (const auto method : {BlendshapeSolveMethod::Bvls, BlendshapeSolveMethod::Ridge, BlendshapeSolveMethod::Temporal})
    EXPECT_EQ(parseBlendshapeSolveMethod(blendshapeSolveMethodName(method)), method);
  EXPECT_EQ(blendshapeSolveMethodNames(), "bvls|ridge|temporal");
  EXPECT_FALSE(parseBlendshapeSolveMethod("nnls"));
}

} // namespace
} // namespace mocap
