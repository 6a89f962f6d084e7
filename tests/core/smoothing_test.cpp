#include "test_support.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/base/error.h"
#include "mocap/model/sample_patch.h"
#include "mocap/cleaning/smoothing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>

namespace mocap {
namespace {

using Trajectory = Eigen::Matrix<double, Eigen::Dynamic, 3>;

std::vector<SmoothOptions> everyMethod()
{
  std::vector<SmoothOptions> list;
  SmoothOptions o;
  o.method = SmoothMethod::BSpline;
  list.push_back(o);
  o.method = SmoothMethod::Butterworth;
  list.push_back(o);
  o.winterCutoff = true;
  list.push_back(o);
  o = {};
  o.method = SmoothMethod::Gcvspl;
  list.push_back(o);
  o.gcvsplDegree = 5;
  list.push_back(o);
  o.gcvsplMode = SmoothingSplineMode::ErrorVariance;
  o.errorVariance = 0.25;
  list.push_back(o);
  o.gcvsplMode = SmoothingSplineMode::Cutoff;
  list.push_back(o);
  o = {};
  o.method = SmoothMethod::SavGol;
  list.push_back(o);
  return list;
}

// Noisy motion in two runs separated by a gap whose positions hold garbage.
Trajectory twoRuns(ValidMask& valid, double secondOffset)
{
  std::mt19937 random(21);
  std::normal_distribution<double> noise(0.0, 0.5);
  Trajectory xyz(300, 3);
  valid = ValidMask::Constant(300, true);
  for (Eigen::Index f = 0; f < 300; ++f)
    for (Eigen::Index c = 0; c < 3; ++c)
      xyz(f, c) = 10.0 * std::sin(0.05 * static_cast<double>(f) + static_cast<double>(c)) + noise(random) +
                  (f >= 160 ? secondOffset : 0.0);
  for (Eigen::Index f = 140; f < 160; ++f) {
    valid(f) = false;
    xyz.row(f) << 1e6, -1e6, std::nan("");
  }
  return xyz;
}

TEST(Smoothing, MethodNamesRoundTrip)
{
  for (SmoothMethod m :
       {SmoothMethod::BSpline, SmoothMethod::Butterworth, SmoothMethod::Gcvspl, SmoothMethod::SavGol})
    EXPECT_EQ(parseSmoothMethod(smoothMethodName(m)), m);
  EXPECT_FALSE(parseSmoothMethod("BSpline"));
  EXPECT_FALSE(parseSmoothMethod(""));
  EXPECT_EQ(smoothMethodName(SmoothOptions{}.method), "gcvspl");
}

TEST(Smoothing, NeverTouchesInvalidSamplesAndNeverMixesRuns)
{
  ValidMask valid;
  const Trajectory near = twoRuns(valid, 0.0);
  const Trajectory far = twoRuns(valid, 500.0);
  for (const SmoothOptions& options : everyMethod()) {
    const Trajectory a = smoothTrajectory(near, valid, 60.0, options);
    const Trajectory b = smoothTrajectory(far, valid, 60.0, options);
    const std::string what = describeSmoothOptions(options);
    for (Eigen::Index f = 140; f < 160; ++f) {
      EXPECT_EQ(a(f, 0), 1e6) << what;
      EXPECT_EQ(a(f, 1), -1e6) << what;
      EXPECT_TRUE(std::isnan(a(f, 2))) << what;
    }
    // Moving the second run by 500 mm changes nothing in the first and only shifts the second.
    if (!options.winterCutoff) {
      EXPECT_EQ(a.topRows(140), b.topRows(140)) << what;
      EXPECT_LT(((b.bottomRows(140).array() - 500.0) - a.bottomRows(140).array()).abs().maxCoeff(), 1e-6)
          << what;
    }
    // And it did smooth: the result differs from the input inside both runs.
    EXPECT_GT((a.topRows(140) - near.topRows(140)).norm(), 1.0) << what;
    EXPECT_GT((a.bottomRows(140) - near.bottomRows(140)).norm(), 1.0) << what;
  }
}

TEST(Smoothing, NonFiniteValidSamplesActAsGapsAndShortRunsStay)
{
  ValidMask valid;
  Trajectory xyz = twoRuns(valid, 0.0);
  xyz(50, 1) = std::numeric_limits<double>::infinity();  // valid but broken
  valid.segment(3, 2).setConstant(false);                // leaves a 3-frame run at the start
  for (const SmoothOptions& options : everyMethod()) {
    const Trajectory out = smoothTrajectory(xyz, valid, 60.0, options);
    EXPECT_EQ(out.row(50), xyz.row(50));
    EXPECT_EQ(out.topRows(3), xyz.topRows(3)) << describeSmoothOptions(options);
    EXPECT_TRUE(out.middleRows(5, 45).allFinite());
  }
}

TEST(Smoothing, EmptyInputsAndAbsurdParameters)
{
  const Trajectory none(0, 3);
  const ValidMask noneValid(0);
  for (const SmoothOptions& options : everyMethod())
    EXPECT_EQ(smoothTrajectory(none, noneValid, 60.0, options).rows(), 0);
  const Trajectory xyz = Trajectory::Random(30, 3);
  EXPECT_THROW((void)smoothTrajectory(xyz, ValidMask::Constant(29, true), 60.0, {}), InvalidArgument);
  EXPECT_THROW((void)smoothTrajectory(xyz, ValidMask::Constant(30, true), 0.0, {}), InvalidArgument);
  EXPECT_THROW((void)smoothTrajectory(xyz, ValidMask::Constant(30, true), std::nan(""), {}), InvalidArgument);
  const auto rejects = [&](auto change) {
    SmoothOptions o;
    change(o);
    EXPECT_THROW((void)smoothTrajectory(xyz, ValidMask::Constant(30, true), 60.0, o), InvalidArgument)
        << describeSmoothOptions(o);
  };
  rejects([](SmoothOptions& o) { o.method = SmoothMethod::BSpline, o.degree = 12; });
  rejects([](SmoothOptions& o) { o.method = SmoothMethod::BSpline, o.knotSpacing = 0.0; });
  rejects([](SmoothOptions& o) { o.method = SmoothMethod::Butterworth, o.cutoffHz = 30.0; });
  rejects([](SmoothOptions& o) { o.method = SmoothMethod::Butterworth, o.cutoffHz = -1.0; });
  rejects([](SmoothOptions& o) { o.method = SmoothMethod::Gcvspl, o.gcvsplDegree = 7; });
  rejects(
      [](SmoothOptions& o) { o.gcvsplMode = SmoothingSplineMode::ErrorVariance, o.errorVariance = -2.0; });
  rejects([](SmoothOptions& o) { o.gcvsplMode = SmoothingSplineMode::Cutoff, o.cutoffHz = 1e9; });
  rejects([](SmoothOptions& o) { o.method = SmoothMethod::SavGol, o.savgolWindow = 8; });
  rejects([](SmoothOptions& o) { o.method = SmoothMethod::SavGol, o.savgolDegree = 9; });
  // Parameters of a method not chosen are not checked.
  SmoothOptions unused;
  unused.degree = 12;
  EXPECT_NO_THROW((void)smoothTrajectory(xyz, ValidMask::Constant(30, true), 60.0, unused));
}

TEST(Smoothing, TakePatchesCoverChangedValidSamplesAndUndoExactly)
{
  Take take = readC3d(test::sampleTake());
  const Take original = take;
  for (const SmoothOptions& options : everyMethod()) {
    const std::vector<SamplePatch> patches = smoothTake(take, options);
    ASSERT_EQ(static_cast<Eigen::Index>(patches.size()), take.markerCount());
    Eigen::Index changed = 0;
    for (std::size_t m = 0; m < patches.size(); ++m) {
      const SamplePatch& patch = patches[m];
      EXPECT_EQ(patch.marker, static_cast<Eigen::Index>(m));
      for (std::size_t i = 0; i < patch.size(); ++i) {
        ASSERT_TRUE(take.isValid(patch.frames[i], patch.marker));
        ASSERT_EQ(patch.states[i], take.state(patch.frames[i], patch.marker).with(SampleOperation::Smoothed));
        ASSERT_EQ(patch.residuals(static_cast<Eigen::Index>(i)),
                  take.residuals()(patch.frames[i], patch.marker));
      }
      changed += static_cast<Eigen::Index>(patch.size());
    }
    EXPECT_GT(changed, take.valid().count() / 2) << describeSmoothOptions(options);
    std::vector<SamplePatch> undo = applyPatches(take, patches);
    EXPECT_TRUE((take.valid() == original.valid()).all());
    applyPatches(take, std::move(undo));
    for (Eigen::Index m = 0; m < take.markerCount(); ++m)
      ASSERT_EQ(take.trajectory(m), original.trajectory(m));
    EXPECT_TRUE((take.states() == original.states()).all());
  }
}

// The batch pipeline's in-place smoothing must leave the take exactly as the studio's patches do,
// including a valid sample holding a NaN (a gap to the filters) and a still marker whose smoothed
// positions may equal the measured ones (not marked smoothed).
TEST(Smoothing, InPlaceLeavesTheTakeAsApplyingThePatches)
{
  Take original = readC3d(test::sampleTake());
  ASSERT_GE(original.markerCount(), 2);
  original.setPosition(200, 0, {std::nan(""), 1.0, 2.0});
  original.valid()(200, 0) = true;
  for (Eigen::Index f = 0; f < original.frameCount(); ++f) {
    original.setPosition(f, 1, {5.0, 5.0, 5.0});
    original.valid()(f, 1) = true;
  }
  for (const SmoothOptions& options : everyMethod()) {
    Take patched = original;
    const std::vector<SamplePatch> patches = smoothTake(original, options);
    Eigen::Index patchedCount = 0;
    for (const SamplePatch& patch : patches)
      patchedCount += static_cast<Eigen::Index>(patch.size());
    applyPatches(patched, patches);
    Take inPlace = original;
    EXPECT_EQ(smoothTakeInPlace(inPlace, options), patchedCount) << describeSmoothOptions(options);
    EXPECT_GT(patchedCount, 0);
    for (Eigen::Index m = 0; m < original.markerCount(); ++m) {
      const auto a = patched.trajectory(m), b = inPlace.trajectory(m);
      ASSERT_TRUE(((a.array() == b.array()) || (a.array().isNaN() && b.array().isNaN())).all())
          << describeSmoothOptions(options) << " marker " << m;
    }
    EXPECT_TRUE((std::as_const(patched).states() == std::as_const(inPlace).states()).all());
    EXPECT_TRUE((patched.valid() == inPlace.valid()).all());
    EXPECT_TRUE((patched.residuals() == inPlace.residuals()).all());
  }
}

TEST(Smoothing, AFilledSampleStaysFilledAndUndoRestoresItsState)
{
  // A smoothed fill is still invented data: smoothing adds an operation, it does not replace the
  // origin (it used to, and `mocap info` then counted no filled samples after a default clean).
  Take take({"a"}, 60, 100.0);
  std::mt19937 noise(7);
  std::normal_distribution<double> jitter(0.0, 0.5);
  for (Eigen::Index f = 0; f < 60; ++f) {
    take.setPosition(f, 0, Eigen::Vector3d(static_cast<double>(f) + jitter(noise), jitter(noise), 0.0));
    take.valid()(f, 0) = true;
  }
  for (Eigen::Index f = 20; f < 30; ++f)
    take.setState(f, 0, SampleOrigin::Filled);
  take.setState(40, 0, SampleOrigin::Edited);
  const Take original = take;
  const std::vector<SamplePatch> patches = smoothTake(take, SmoothOptions{});
  ASSERT_EQ(patches.size(), 1u);
  std::vector<SamplePatch> undo = applyPatches(take, patches);
  EXPECT_EQ(take.state(25, 0), SampleState(SampleOrigin::Filled).with(SampleOperation::Smoothed));
  EXPECT_EQ(take.state(40, 0), SampleState(SampleOrigin::Edited).with(SampleOperation::Smoothed));
  EXPECT_EQ(take.state(10, 0), SampleState().with(SampleOperation::Smoothed));
  Take inPlace = original;
  (void)smoothTakeInPlace(inPlace, SmoothOptions{});
  EXPECT_TRUE((std::as_const(inPlace).states() == std::as_const(take).states()).all());
  applyPatches(take, std::move(undo));
  EXPECT_TRUE((std::as_const(take).states() == original.states()).all());
  EXPECT_EQ(take.state(25, 0), SampleOrigin::Filled);
}

TEST(Smoothing, TakeWithNoFramesOrMarkers)
{
  const Take empty;
  EXPECT_TRUE(smoothTake(empty, {}).empty());
  const Take noFrames({"a", "b"}, 0, 100.0);
  const auto patches = smoothTake(noFrames, {});
  ASSERT_EQ(patches.size(), 2u);
  EXPECT_TRUE(patches[0].empty());
}

} // namespace
} // namespace mocap
