// The one layout planning request (layout_planning.h) that `mocap pfa` and the studio's Layout
// planning panel both run: key poses and globs as users write them, and a plan of the bundled sample
// that must equal the one made step by step.
#include "test_support.h"

#include "mocap/base/text.h"
#include "mocap/io/take_io.h"
#include "mocap/layout/layout_planning.h"
#include "mocap/layout/layout_symmetry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

namespace mocap {
namespace {

using Field = LayoutRequestError::Field;

const std::vector<std::string> kRoots{"root-1", "root-2", "root-3", "root-4", "root-5", "root-6"};

Field fieldOfError(const std::function<void()>& call)
{
  try {
    call();
  } catch (const LayoutRequestError& e) {
    return e.field();
  }
  ADD_FAILURE() << "no LayoutRequestError";
  return Field::Markers;
}

TEST(Glob, StarsAndQuestionMarks)
{
  EXPECT_TRUE(globMatch("section1-*", "section1-2"));
  EXPECT_TRUE(globMatch("*", ""));
  EXPECT_TRUE(globMatch("lip?", "lipL"));
  EXPECT_FALSE(globMatch("lip?", "lip"));
  EXPECT_TRUE(globMatch("*-1*", "section12-10"));
  EXPECT_FALSE(globMatch("section1-*", "section12-1"));
  EXPECT_TRUE(globMatch("a*b*c", "aXbYbZc"));
  EXPECT_FALSE(globMatch("a*b*c", "aXbYbZ"));
}

TEST(LayoutRequest, KeyPosesAsUsersWriteThem)
{
  EXPECT_TRUE(parseKeyPoses("auto").empty());
  EXPECT_TRUE(parseKeyPoses("  ").empty());
  const std::vector<KeyPose> poses = parseKeyPoses("12, 2:40");
  ASSERT_EQ(poses.size(), 2U);
  EXPECT_EQ(poses[0].take, 0U);
  EXPECT_EQ(poses[0].frame, 12);
  EXPECT_EQ(poses[1].take, 1U);
  EXPECT_EQ(poses[1].frame, 40);
  for (const char* bad : {"x", "0:5", "1:", ":5", "1,,2", "+3", "1.5", "a:3", "2:b"})
    EXPECT_EQ(fieldOfError([&] { (void)parseKeyPoses(bad); }), Field::KeyPoses) << bad;
}

TEST(LayoutRequest, GlobsKeepTakeOrderAndNameAPatternThatMatchesNothing)
{
  const std::vector<std::string> labels{"b-1", "a-1", "b-2", "c"};
  EXPECT_EQ(labelsMatching(labels, {"c", "b-*"}, Field::Markers), (std::vector<std::string>{"b-1", "b-2", "c"}));
  try {
    (void)labelsMatching(labels, {"b-*", "z?"}, Field::Exclude);
    FAIL() << "a pattern that matches nothing must be refused";
  } catch (const LayoutRequestError& e) {
    EXPECT_EQ(e.field(), Field::Exclude);
    EXPECT_NE(std::string(e.what()).find("'z?'"), std::string::npos) << e.what();
  }
}

class SamplePlan : public ::testing::Test
{
protected:
  static LayoutRequest quickRequest()
  {
    LayoutRequest request;
    request.stabilizeLabels = kRoots;
    request.plan.pfa.restarts = 20;
    request.plan.pfa.minK = 6;
    request.plan.pfa.maxK = 9;
    request.plan.randomSubsets = 3;
    return request;
  }
  std::vector<Take> takes{readTake(test::sampleTake())};
};

TEST_F(SamplePlan, EqualsThePlanMadeStepByStep)
{
  // The plan made by hand from the documented steps: frames, key poses, pairs, plan.
  LayoutFramesOptions frameOptions;
  frameOptions.stabilizeLabels = kRoots;
  for (const std::string& label : defaultPlannedLabels(takes.front(), kRoots))
    if (!globMatch("section1-*", label))
      frameOptions.markers.push_back(label);
  const LayoutFrames frames = collectLayoutFrames(takes, frameOptions);
  LayoutRequest request = quickRequest();
  request.excludePatterns = {"section1-*"};
  LayoutPlanOptions options = request.plan;
  for (const std::size_t share : {std::size_t{10}, std::size_t{45}, std::size_t{80}}) {  // three training frames, as frame numbers
    const Eigen::Index row = frames.training[frames.training.size() * share / 100];
    options.keyFrames.push_back(row);
    request.keyPoses.push_back({0, frames.origin[static_cast<std::size_t>(row)].second + takes.front().firstFrame()});
  }
  const PairDetection pairs = detectLayoutPairs(frames, options.keyFrames);
  const LayoutPlan plan = planMarkerLayout(frames, pairs.symmetry, options);

  const LayoutResult result = planLayout(takes, request);
  // The planned markers: every labelled marker but the reference markers and section1-*.
  ASSERT_FALSE(result.frames.labels.empty());
  for (const std::string& label : result.frames.labels) {
    EXPECT_EQ(std::find(kRoots.begin(), kRoots.end(), label), kRoots.end()) << label;
    EXPECT_FALSE(globMatch("section1-*", label)) << label;
  }
  EXPECT_EQ(frames.labels, result.frames.labels);
  EXPECT_TRUE(result.frames.stabilized);
  EXPECT_EQ(result.plan.basis.keyFrames, options.keyFrames);
  ASSERT_TRUE(result.detection.has_value()) << "no pairs file: the pairs are detected";
  EXPECT_EQ(result.symmetry.pairs(), pairs.symmetry.pairs());
  EXPECT_EQ(result.plan.recommendedSize, plan.recommendedSize);
  ASSERT_EQ(result.plan.sizes.size(), plan.sizes.size());
  for (std::size_t i = 0; i < plan.sizes.size(); ++i) {
    EXPECT_EQ(result.plan.sizes[i].markerCount, plan.sizes[i].markerCount);
    const ScoredLayout* mine = result.plan.sizes[i].layout(plan.method);
    const ScoredLayout* theirs = plan.sizes[i].layout(plan.method);
    ASSERT_EQ(mine != nullptr, theirs != nullptr);
    if (mine) {
      EXPECT_EQ(mine->markers, theirs->markers);
    }
  }

  // A capture with the recommended layout records its markers and the reference markers.
  const ScoredLayout* recommended = result.layout(result.plan.recommendedSize);
  ASSERT_NE(recommended, nullptr);
  const std::vector<std::string> capture = result.captureLabels(recommended);
  EXPECT_EQ(capture.size(), recommended->markers.size() + kRoots.size());
  EXPECT_TRUE(std::equal(kRoots.begin(), kRoots.end(), capture.end() - static_cast<std::ptrdiff_t>(kRoots.size())));
}

TEST_F(SamplePlan, RefusesWhatTheTakesDoNotHave)
{
  LayoutRequest request = quickRequest();
  request.markerPatterns = {"no-such-*"};
  EXPECT_EQ(fieldOfError([&] { (void)planLayout(takes, request); }), Field::Markers);
  request = quickRequest();
  request.keyPoses = {{0, 1'000'000}};
  EXPECT_EQ(fieldOfError([&] { (void)planLayout(takes, request); }), Field::KeyPoses);
  request.keyPoses = {{1, 10}};
  EXPECT_EQ(fieldOfError([&] { (void)planLayout(takes, request); }), Field::KeyPoses) << "there is no take 2";
  request.keyPoses = {{0, 300}, {0, 300}};
  EXPECT_EQ(fieldOfError([&] { (void)planLayout(takes, request); }), Field::KeyPoses) << "given twice";
  EXPECT_THROW((void)planLayout({}, quickRequest()), InvalidArgument);
}

} // namespace
} // namespace mocap
