#include "face_mesh_fixture.h"

#include "mocap/base/error.h"
#include "mocap/io/obj_io.h"
#include "mocap/deform/rbf_deformer.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace mocap {
namespace {

const Mesh& face()
{
  return test::mediaPipeFace();
}

// Every 15th vertex as a control (32 controls spread over the face).
std::vector<Eigen::Index> controlVertices()
{
  return test::everyNthVertex(0, 15);
}

PointSet rowsOf(const MeshVertices& vertices, const std::vector<Eigen::Index>& rows)
{
  return vertices(rows, Eigen::all);
}

const RbfKernel kKernels[] = {RbfKernel::Exp, RbfKernel::Gaussian, RbfKernel::Biharmonic, RbfKernel::ThinPlate};

RbfOptions optionsFor(RbfKernel kernel, bool regions = false)
{
  RbfOptions options;
  options.kernel = kernel;
  options.radius = kernel == RbfKernel::Gaussian ? 6.0 : 64.0;  // a Gaussian of 64 cm is flat on a 17 cm face
  options.regions = regions;
  return options;
}

TEST(RbfDeformer, AffineTermReproducesRigidMotionForEveryKernel)
{
  const std::vector<Eigen::Index> controls = controlVertices();
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, 1.0, -0.4).normalized()).toRotationMatrix();
  motion.translation() = Eigen::Vector3d(1.5, -0.7, 2.0);
  const MeshVertices moved = (face().vertices * motion.linear().transpose()).rowwise() + motion.translation().transpose();
  for (const bool regions : {false, true})
    for (const RbfKernel kernel : kKernels) {
      const RbfDeformer deformer(face().vertices, rowsOf(face().vertices, controls), optionsFor(kernel, regions));
      MeshVertices out;
      deformer.deform(rowsOf(moved, controls) - rowsOf(face().vertices, controls), out);
      EXPECT_LT((out - moved).cwiseAbs().maxCoeff(), 1e-5 * face().size())
          << rbfKernelName(kernel) << (regions ? " with regions" : "");
    }
}

TEST(RbfDeformer, ZeroDisplacementLeavesTheMeshUnchanged)
{
  const std::vector<Eigen::Index> controls = controlVertices();
  for (const RbfKernel kernel : kKernels) {
    const RbfDeformer deformer(face().vertices, rowsOf(face().vertices, controls), optionsFor(kernel, true));
    MeshVertices out;
    deformer.deform(PointSet::Zero(static_cast<Eigen::Index>(controls.size()), 3), out);
    EXPECT_EQ(out, face().vertices);
  }
}

TEST(RbfDeformer, InterpolatesControlsExactlyWithAndWithoutRegionsOrAffineTerm)
{
  const std::vector<Eigen::Index> controls = controlVertices();
  const PointSet displacements = PointSet::Random(static_cast<Eigen::Index>(controls.size()), 3) * 0.8;
  for (const bool regions : {false, true})
    for (const bool affine : {false, true})
      for (const RbfKernel kernel : {RbfKernel::Exp, RbfKernel::Gaussian, RbfKernel::Biharmonic}) {
        RbfOptions options = optionsFor(kernel, regions);
        options.affine = affine;
        const RbfDeformer deformer(face().vertices, rowsOf(face().vertices, controls), options);
        MeshVertices out;
        deformer.deform(displacements, out);
        const PointSet reached = rowsOf(out, controls) - rowsOf(face().vertices, controls);
        EXPECT_LT((reached - displacements).cwiseAbs().maxCoeff(), 1e-5)
            << rbfKernelName(kernel) << " regions " << regions << " affine " << affine;
      }
}

TEST(RbfDeformer, PrecomputedResponseMatchesTheNaivePerVertexEvaluation)
{
  const std::vector<Eigen::Index> controls = controlVertices();
  const PointSet displacements = PointSet::Random(static_cast<Eigen::Index>(controls.size()), 3);
  for (const RbfKernel kernel : kKernels) {
    const RbfDeformer deformer(face().vertices, rowsOf(face().vertices, controls), optionsFor(kernel));
    MeshVertices fast, direct;
    deformer.deform(displacements, fast);
    deformer.deformDirect(displacements, direct);
    EXPECT_LT((fast - direct).cwiseAbs().maxCoeff(), 1e-4) << rbfKernelName(kernel);
  }
}

// The largest difference of displacement between the two ends of a mesh edge.
double largestEdgeJump(const MeshVertices& moved)
{
  double largest = 0.0;
  for (const Triangle& t : face().triangles())
    for (std::size_t e = 0; e < 3; ++e)
      largest = std::max(largest, (moved.row(t[e]) - moved.row(t[(e + 1) % 3])).norm());
  return largest;
}

TEST(RbfDeformer, RegionsBlendSmoothlyWithoutSeams)
{
  // Opposing vertical displacements of the upper and lower controls (the paper's Fig. 4 case).
  const std::vector<Eigen::Index> controls = controlVertices();
  const PointSet rest = rowsOf(face().vertices, controls);
  PointSet displacements = PointSet::Zero(rest.rows(), 3);
  const double middle = 0.5 * (rest.col(1).minCoeff() + rest.col(1).maxCoeff());
  for (Eigen::Index c = 0; c < rest.rows(); ++c)
    displacements(c, 1) = rest(c, 1) > middle ? 1.0 : -1.0;
  const auto jump = [&](double blendWidth) {
    RbfOptions options = optionsFor(RbfKernel::Exp, true);
    options.blendWidth = blendWidth;
    const RbfDeformer deformer(face().vertices, rest, options);
    // Rows of the response sum to 1 (a translation is reproduced) across the blend bands too
    // (up to the single-precision storage of the response).
    EXPECT_LT((deformer.response().rowwise().sum().array() - 1.0f).abs().maxCoeff(), 1e-5f);
    MeshVertices out;
    deformer.deform(displacements, out);
    return largestEdgeJump(out - face().vertices);
  };
  // A band of 0.2 % of the height is practically a seam between the regions' fields.
  const double seam = jump(0.002);
  const double blended = jump(0.1);
  EXPECT_LT(blended, 0.8 * seam) << "blended " << blended << " seam " << seam;
}

TEST(RbfDeformer, MissingControlIsSkippedLikeADeformerWithoutIt)
{
  const std::vector<Eigen::Index> controls = controlVertices();
  const PointSet rest = rowsOf(face().vertices, controls);
  const PointSet displacements = PointSet::Random(rest.rows(), 3);
  RbfDeformer deformer(face().vertices, rest, optionsFor(RbfKernel::Exp));
  std::vector<bool> present(controls.size(), true);
  present[3] = false;
  PointSet withNan = displacements;
  withNan.row(3).setConstant(std::nan(""));  // a missing marker's row is never read
  MeshVertices skipped;
  deformer.deform(withNan, present, skipped);

  std::vector<Eigen::Index> fewer = controls;
  fewer.erase(fewer.begin() + 3);
  PointSet fewerDisplacements(rest.rows() - 1, 3);
  fewerDisplacements << displacements.topRows(3), displacements.bottomRows(rest.rows() - 4);
  const RbfDeformer reference(face().vertices, rowsOf(face().vertices, fewer), optionsFor(RbfKernel::Exp));
  MeshVertices expected;
  reference.deform(fewerDisplacements, expected);
  EXPECT_LT((skipped - expected).cwiseAbs().maxCoeff(), 1e-5);

  std::vector<bool> none(controls.size(), false);
  deformer.deform(withNan, none, skipped);
  EXPECT_EQ(skipped, face().vertices);
}

TEST(RbfDeformer, RejectsDuplicateControlsAndBadOptions)
{
  PointSet rest = rowsOf(face().vertices, controlVertices());
  rest.row(5) = rest.row(2);
  try {
    const RbfDeformer deformer(face().vertices, rest);
    ADD_FAILURE() << "duplicate controls accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("controls 3 and 6 are at the same mesh point"), std::string::npos) << e.what();
  }
  const PointSet distinct = rowsOf(face().vertices, controlVertices());
  RbfOptions bad;
  bad.radius = 0.0;
  EXPECT_THROW(RbfDeformer(face().vertices, distinct, bad), InvalidArgument);
  EXPECT_THROW(RbfDeformer(face().vertices, distinct.topRows(3)), InvalidArgument);  // affine needs 4
  EXPECT_THROW(RbfDeformer(face().vertices, PointSet(0, 3)), InvalidArgument);
  PointSet coplanar = distinct.topRows(6);
  coplanar.col(2).setZero();
  coplanar.col(1).setZero();  // collinear: the affine block is singular
  EXPECT_THROW(RbfDeformer(face().vertices, coplanar), InvalidArgument);
  const RbfDeformer deformer(face().vertices, distinct);
  MeshVertices out;
  EXPECT_THROW(deformer.deform(PointSet::Zero(3, 3), out), InvalidArgument);
  PointSet nan = PointSet::Zero(distinct.rows(), 3);
  nan(0, 0) = std::nan("");
  EXPECT_THROW(deformer.deform(nan, out), InvalidArgument);
}

TEST(RbfDeformer, KernelNamesRoundTrip)
{
  for (const RbfKernel kernel : kKernels)
    EXPECT_EQ(parseRbfKernel(rbfKernelName(kernel)), kernel);
  EXPECT_FALSE(parseRbfKernel("cubic"));
  EXPECT_DOUBLE_EQ(rbfKernel(RbfKernel::Exp, 64.0, 64.0), std::exp(-1.0));
  EXPECT_DOUBLE_EQ(rbfKernel(RbfKernel::ThinPlate, 0.0, 1.0), 0.0);
}

} // namespace
} // namespace mocap
