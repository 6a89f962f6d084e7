// Marker layouts judged on a blendshape rig (evaluation/layout_rig_error.h): the MSE between the
// weights solved from a layout and from every bound marker, on a synthetic rig and take.
#include "face_mesh_fixture.h"

#include "mocap/base/error.h"
#include "mocap/base/random.h"
#include "mocap/evaluation/layout_rig_error.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <atomic>
#include <cmath>

namespace mocap {
namespace {

// Six shapes on the MediaPipe face (cm): shape s pulls the vertices within 5 cm of one centre
// along one axis, by a cone falling linearly to 0 at the rim.
const BlendshapeRig& pullRig()
{
  static const BlendshapeRig rig = [] {
    BlendshapeRig r;
    r.neutral = test::mediaPipeFace();
    const Eigen::Index centres[] = {1, 13, 61, 291, 105, 334};
    for (int s = 0; s < 6; ++s) {
      const Eigen::RowVector3d centre = r.neutral.vertices.row(centres[s]);
      MeshVertices pulled = r.neutral.vertices;
      for (Eigen::Index v = 0; v < pulled.rows(); ++v) {
        const double reach = 1.0 - (pulled.row(v) - centre).norm() / 5.0;
        pulled(v, s % 3) += reach > 0.0 ? 0.7 * reach : 0.0;
      }
      r.shapes.push_back(sparseShape("pull" + std::to_string(s), r.neutral.vertices, pulled, 1e-12));
    }
    return r;
  }();
  return rig;
}

// Four head markers off the face (cm), carried by the head only.
const Eigen::Vector3d kHeadMarkers[] = {{0, 12, 4}, {8, 8, 0}, {-8, 8, 0}, {0, 10, -6}};

struct Capture
{
  Take take;
  MeshBinding binding;
  std::vector<std::string> face;  // the bound markers' labels
};

// Markers on every 15th vertex posed by smooth weights (frame 0 neutral), in mm, with 0.3 mm of
// noise per coordinate; with `headMotion` the whole head also turns and drifts.
Capture capture(bool headMotion, Eigen::Index frames = 400)
{
  Capture c;
  const BlendshapeRig& rig = pullRig();
  const std::vector<Eigen::Index> vertices = test::everyNthVertex(5, 15);
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    c.face.push_back("f" + std::to_string(i));
    c.binding.markers.push_back({c.face.back(), MeshPoint::atVertex(vertices[i]), 0.0});
  }
  c.binding.meshVertices = rig.neutral.vertexCount();
  labels = c.face;
  for (int h = 0; h < 4; ++h)
    labels.push_back("head" + std::to_string(h));
  c.take = Take(labels, frames, 100.0);
  Random random(5);
  MeshVertices posed;
  Eigen::VectorXd w(rig.shapeCount());
  for (Eigen::Index f = 0; f < frames; ++f) {
    for (Eigen::Index s = 0; s < w.size(); ++s)
      w(s) = f == 0 ? 0.0 : 0.5 - 0.5 * std::cos(0.05 * static_cast<double>(f) * (1.0 + 0.37 * static_cast<double>(s)));
    rig.evaluate(w, posed);
    const double t = headMotion ? static_cast<double>(f) / 100.0 : 0.0;
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.2 * std::sin(t), Eigen::Vector3d::UnitY()).toRotationMatrix();
    const Eigen::Vector3d drift(15.0 * t, 0.0, -5.0 * t);
    const auto place = [&](const Eigen::Vector3d& cm) { return Eigen::Vector3d(turn * (10.0 * cm) + drift); };
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      Eigen::Vector3d p = posed.row(vertices[i]).transpose();
      if (f > 0)
        p += 0.03 * Eigen::Vector3d(random.normal(), random.normal(), random.normal());
      c.take.setPosition(f, static_cast<Eigen::Index>(i), place(p));
      c.take.valid()(f, static_cast<Eigen::Index>(i)) = true;
    }
    for (int h = 0; h < 4; ++h) {
      const auto m = static_cast<Eigen::Index>(vertices.size()) + h;
      c.take.setPosition(f, m, place(kHeadMarkers[h]));
      c.take.valid()(f, m) = true;
    }
  }
  return c;
}

const std::vector<std::string> kHeads{"head0", "head1", "head2", "head3"};

// Every `step`-th of the face markers.
std::vector<std::string> everyNth(const std::vector<std::string>& labels, std::size_t step)
{
  std::vector<std::string> picked;
  for (std::size_t i = 0; i < labels.size(); i += step)
    picked.push_back(labels[i]);
  return picked;
}

LayoutRigErrors judge(const Capture& c, const std::vector<std::vector<std::string>>& layouts,
                      LayoutRigErrorOptions options = {}, const JobControl& control = {})
{
  if (options.stabilizeLabels.empty())
    options.stabilizeLabels = kHeads;
  return layoutRigErrors({c.take}, pullRig(), c.binding, layouts, options, control);
}

TEST(LayoutRigError, TheFullLayoutGivesZeroAndDroppingMarkersGivesMore)
{
  const Capture c = capture(true);
  std::vector<std::string> allButOne = c.face;
  allButOne.erase(allButOne.begin() + 7);
  const LayoutRigErrors r = judge(c, {c.face, allButOne, everyNth(c.face, 6)});
  ASSERT_EQ(r.layouts.size(), 3U);
  EXPECT_FALSE(r.cancelled);
  EXPECT_EQ(r.boundMarkers, static_cast<Eigen::Index>(c.face.size()));
  EXPECT_EQ(r.frames, 400);
  EXPECT_EQ(r.layouts[0].boundMarkers, r.boundMarkers);
  EXPECT_EQ(r.layouts[0].frames, 400);
  EXPECT_EQ(r.layouts[0].mse, 0.0);
  EXPECT_GT(r.layouts[1].mse, 0.0);
  // Six markers miss whole shapes' regions: those weights are lost, not just noisier.
  EXPECT_GT(r.layouts[2].mse, 100.0 * r.layouts[1].mse);
}

TEST(LayoutRigError, HeadMotionIsRemovedWithTheReferenceMarkers)
{
  // The same face and noise with and without head motion: once stabilized they judge alike.
  const Capture moving = capture(true), still = capture(false);
  const std::vector<std::vector<std::string>> layouts{everyNth(moving.face, 2)};
  const double stabilized = judge(moving, layouts).layouts[0].mse;
  EXPECT_NEAR(stabilized, judge(still, layouts).layouts[0].mse, 1e-6 * stabilized);
  const double raw = layoutRigErrors({moving.take}, pullRig(), moving.binding, layouts).layouts[0].mse;
  EXPECT_GT(std::abs(raw - stabilized), 0.5 * stabilized) << "head motion left in changes the weights";
}

TEST(LayoutRigError, UnboundMarkersAddNothingAndTooFewAreNotJudged)
{
  const Capture c = capture(false);
  std::vector<std::string> withHeads = everyNth(c.face, 2);
  withHeads.insert(withHeads.end(), kHeads.begin(), kHeads.end());
  withHeads.push_back("not-in-the-take");
  const LayoutRigErrors r = judge(c, {everyNth(c.face, 2), withHeads, {"f0", "f1", "head0", "head1"}, {}});
  EXPECT_EQ(r.layouts[1].boundMarkers, r.layouts[0].boundMarkers);
  EXPECT_EQ(r.layouts[1].mse, r.layouts[0].mse);
  for (const std::size_t i : {2U, 3U}) {
    EXPECT_FALSE(r.layouts[i].judged()) << i;
    EXPECT_TRUE(std::isnan(r.layouts[i].mse));
    EXPECT_EQ(r.layouts[i].frames, 0);
  }
  EXPECT_EQ(r.layouts[2].boundMarkers, 2);
  EXPECT_EQ(r.layouts[3].boundMarkers, 0);
}

TEST(LayoutRigError, TheSameOnAnyThreadCount)
{
  const Capture c = capture(true);
  std::vector<std::vector<std::string>> layouts;
  for (std::size_t step = 1; step <= 6; ++step)
    layouts.push_back(everyNth(c.face, step));
  std::vector<double> first;
  for (const int threads : {1, 2, 4}) {
    const LayoutRigErrors r = judge(c, layouts, {}, JobControl().withThreads(threads));
    std::vector<double> mse;
    for (const RigLayoutError& e : r.layouts)
      mse.push_back(e.mse);
    if (first.empty())
      first = mse;
    EXPECT_EQ(mse, first) << threads << " threads";
  }
}

TEST(LayoutRigError, SolvesAtMostTheFramesAskedForAndEverySolverMethod)
{
  const Capture c = capture(true);
  const std::vector<std::vector<std::string>> layouts{c.face, everyNth(c.face, 2)};
  LayoutRigErrorOptions options;
  options.maxFrames = 70;  // 400 frames: every 6th from the neutral frame 0, 67 frames
  const LayoutRigErrors few = judge(c, layouts, options);
  EXPECT_EQ(few.frames, 67);
  EXPECT_EQ(few.layouts[1].frames, 67);
  const double all = judge(c, layouts).layouts[1].mse;
  EXPECT_NEAR(few.layouts[1].mse, all, 0.5 * all);  // a sample of the same error
  for (const auto method : {BlendshapeSolveMethod::Ridge, BlendshapeSolveMethod::Temporal}) {
    options.solve.method = method;
    const LayoutRigErrors r = judge(c, layouts, options);
    EXPECT_EQ(r.layouts[0].mse, 0.0) << blendshapeSolveMethodName(method);
    EXPECT_GT(r.layouts[1].mse, 0.0);
  }
}

TEST(LayoutRigError, PoolsTheTakesAndStopsOnCancel)
{
  const Capture a = capture(true), b = capture(false, 200);
  const std::vector<std::vector<std::string>> layouts{everyNth(a.face, 2)};
  LayoutRigErrorOptions options;
  options.stabilizeLabels = kHeads;
  const LayoutRigErrors both = layoutRigErrors({a.take, b.take}, pullRig(), a.binding, layouts, options);
  EXPECT_EQ(both.frames, 600);
  EXPECT_EQ(both.layouts[0].frames, 600);
  const double onlyA = judge(a, layouts).layouts[0].mse, onlyB = judge(b, layouts).layouts[0].mse;
  EXPECT_NEAR(both.layouts[0].mse, (400.0 * onlyA + 200.0 * onlyB) / 600.0, 1e-9 * onlyA);

  const JobControl cancelled({}, std::make_shared<std::atomic<bool>>(true));
  const LayoutRigErrors stopped = judge(a, layouts, {}, cancelled);
  EXPECT_TRUE(stopped.cancelled);
  ASSERT_EQ(stopped.layouts.size(), 1U);
  EXPECT_FALSE(stopped.layouts[0].judged());
}

TEST(LayoutRigError, BadInputGivesAClearError)
{
  const Capture c = capture(false, 50);
  EXPECT_THROW((void)layoutRigErrors({}, pullRig(), c.binding, {c.face}), InvalidArgument);
  LayoutRigErrorOptions options;
  options.maxFrames = -1;
  EXPECT_THROW((void)judge(c, {c.face}, options), InvalidArgument);
  MeshBinding otherMesh = c.binding;
  otherMesh.meshVertices = 10;
  EXPECT_THROW((void)layoutRigErrors({c.take}, pullRig(), otherMesh, {c.face}), InvalidArgument);
  MeshBinding missing = c.binding;
  missing.markers.push_back({"nowhere", MeshPoint::atVertex(0), 0.0});
  EXPECT_THROW((void)layoutRigErrors({c.take}, pullRig(), missing, {c.face}), InvalidArgument);
  options = {};
  options.stabilizeLabels = {"head0", "nowhere"};
  EXPECT_THROW((void)layoutRigErrors({c.take}, pullRig(), c.binding, {c.face}, options), InvalidArgument);
}

TEST(LayoutRigError, JudgesEverySizeOfAPlan)
{
  const Capture c = capture(true, 600);  // five one-second blocks: one held out for testing
  LayoutRequest request;
  request.stabilizeLabels = kHeads;
  request.plan.pfa.restarts = 10;
  request.plan.pfa.minK = 2;
  request.plan.pfa.maxK = 6;
  request.plan.randomSubsets = 3;
  const LayoutResult plan = planLayout({c.take}, request);
  LayoutRigErrorOptions options;
  options.randomSubsets = 4;
  const PlanRigErrors r = planRigErrors({c.take}, plan, pullRig(), c.binding, options);
  ASSERT_EQ(r.sizes.size(), plan.plan.sizes.size());
  EXPECT_EQ(r.planned.mse, 0.0);
  EXPECT_EQ(r.planned.boundMarkers, static_cast<Eigen::Index>(c.face.size()));
  for (std::size_t s = 0; s < r.sizes.size(); ++s) {
    const LayoutSize& size = plan.plan.sizes[s];
    const LayoutSizeRigErrors& entry = r.sizes[s];
    EXPECT_EQ(entry.markerCount, size.markerCount);
    EXPECT_EQ(entry.pfa.has_value(), size.pfa.has_value()) << size.markerCount;
    EXPECT_EQ(entry.greedy.has_value(), size.greedy.has_value()) << size.markerCount;
    EXPECT_EQ(r.size(size.markerCount), &entry);
    if (size.markerCount >= kMinimumRigLayoutMarkers) {
      EXPECT_EQ(entry.randomCount, size.randomCount > 0 ? 4 : 0) << size.markerCount;
      if (entry.randomCount > 0) {
        EXPECT_GT(entry.randomMse, 0.0) << size.markerCount;
      }
    } else {
      EXPECT_EQ(entry.randomCount, 0);
      EXPECT_TRUE(std::isnan(entry.randomMse));
      if (entry.pfa) {
        EXPECT_FALSE(entry.pfa->judged());
      }
    }
  }
  EXPECT_EQ(r.size(0), nullptr);
  options.randomSubsets = -1;
  EXPECT_THROW((void)planRigErrors({c.take}, plan, pullRig(), c.binding, options), InvalidArgument);
}

} // namespace
} // namespace mocap
