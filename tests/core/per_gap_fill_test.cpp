#include "mocap/base/error.h"
#include "mocap/cleaning/fill/per_gap_fill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

namespace mocap {
namespace {

// Four markers moving smoothly over 200 frames at 100 Hz (the default rules fill up to 50 frames).
Take movingTake()
{
  Take take({"a", "b", "c", "d"}, 200, 100.0);
  take.valid().setConstant(true);
  take.residuals().setZero();
  for (Eigen::Index f = 0; f < 200; ++f)
    for (Eigen::Index m = 0; m < 4; ++m) {
      const double t = 0.02 * static_cast<double>(f) + static_cast<double>(m);
      take.setPosition(f, m, Eigen::Vector3d(10 * std::sin(t), 20 * static_cast<double>(m) + std::cos(t),
                                             0.1 * static_cast<double>(f)));
    }
  return take;
}

Gap hide(Take& take, Eigen::Index marker, Eigen::Index first, Eigen::Index length)
{
  for (Eigen::Index f = first; f < first + length; ++f) {
    take.valid()(f, marker) = false;
    take.residuals()(f, marker) = -1.0;
  }
  return Gap{marker, first, length, first == 0 || first + length == take.frameCount()};
}

TEST(PerGapFill, NoGapIsAnEmptyResult)
{
  const FillResult result = fillEachGap(movingTake(), {}, {}, {}, FillOptions{});
  EXPECT_TRUE(result.gaps.empty());
  EXPECT_TRUE(result.patches.empty());
}

TEST(PerGapFill, ChoicesOfAnotherLengthAreAClearError)
{
  Take take = movingTake();
  const Gap gap = hide(take, 0, 10, 5);
  EXPECT_THROW((void)fillEachGap(take, {gap}, {}, {false}, FillOptions{}), InvalidArgument);
  EXPECT_THROW((void)fillEachGap(take, {gap}, {FillMethod::Linear}, {false, true}, FillOptions{}), InvalidArgument);
}

// Each gap with its own method fills exactly as fillGaps fills it alone; reports follow the gaps.
TEST(PerGapFill, EachGapFillsAsItWouldAlone)
{
  Take take = movingTake();
  const std::vector<Gap> gaps{hide(take, 2, 40, 8), hide(take, 0, 100, 12), hide(take, 1, 20, 6)};
  const std::vector<FillMethod> methods{FillMethod::Linear, FillMethod::Spline, FillMethod::Linear};
  const FillResult result = fillEachGap(take, gaps, methods, {false, false, false}, FillOptions{});
  ASSERT_EQ(result.gaps.size(), 3u);
  ASSERT_EQ(result.patches.size(), 3u);
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    EXPECT_TRUE(result.gaps[i].filled);
    EXPECT_EQ(result.gaps[i].gap.marker, gaps[i].marker);
    FillOptions alone;
    alone.method = methods[i];
    const FillResult single = fillGaps(take, {gaps[i]}, alone);
    ASSERT_EQ(single.patches.size(), 1u);
    const auto patch = std::find_if(result.patches.begin(), result.patches.end(),
                                    [&](const SamplePatch& p) { return p.marker == gaps[i].marker; });
    ASSERT_NE(patch, result.patches.end());
    EXPECT_EQ(patch->frames, single.patches.front().frames);
    EXPECT_TRUE(patch->positions.isApprox(single.patches.front().positions, 0.0));
  }
  // Patches in marker order, whatever the order of the gaps.
  EXPECT_EQ(result.patches[0].marker, 0);
  EXPECT_EQ(result.patches[1].marker, 1);
  EXPECT_EQ(result.patches[2].marker, 2);
}

TEST(PerGapFill, AGapOverTheLimitIsFilledOnlyPastTheRules)
{
  Take take = movingTake();
  const Gap tooLong = hide(take, 3, 60, 70);  // 0.7 s, over the default 0.5 s
  const FillResult kept = fillEachGap(take, {tooLong}, {FillMethod::Linear}, {false}, FillOptions{});
  ASSERT_EQ(kept.gaps.size(), 1u);
  EXPECT_FALSE(kept.gaps[0].filled);
  EXPECT_EQ(kept.gaps[0].cause, UnfilledCause::TooLong);
  EXPECT_TRUE(kept.patches.empty());
  const FillResult past = fillEachGap(take, {tooLong}, {FillMethod::Linear}, {true}, FillOptions{});
  EXPECT_TRUE(past.gaps[0].filled);
  ASSERT_EQ(past.patches.size(), 1u);
  EXPECT_EQ(past.patches[0].size(), 70u);
}

// Past the rules an edge gap is extrapolated and a rarely seen marker filled; a marker never seen
// stays open whatever the user allows.
TEST(PerGapFill, PastTheRulesLiftsAllButNeverSeen)
{
  Take take = movingTake();
  const Gap edge = hide(take, 0, 0, 2);
  const Gap never = hide(take, 1, 0, 200);
  FillOptions rules;
  rules.minValidFraction = 0.99;  // marker c below (97.5 % seen) is rarely seen under these rules
  const Gap rare = hide(take, 2, 100, 5);
  const std::vector<FillMethod> methods(3, FillMethod::Guenter);
  const FillResult kept = fillEachGap(take, {edge, never, rare}, methods, {false, false, false}, rules);
  EXPECT_EQ(kept.gaps[0].cause, UnfilledCause::EdgeGap);
  EXPECT_EQ(kept.gaps[1].cause, UnfilledCause::NeverValid);
  EXPECT_EQ(kept.gaps[2].cause, UnfilledCause::RarelyValid);
  const FillResult past = fillEachGap(take, {edge, never, rare}, methods, {true, true, true}, rules);
  EXPECT_TRUE(past.gaps[0].filled);
  EXPECT_EQ(past.gaps[1].cause, UnfilledCause::NeverValid);
  EXPECT_TRUE(past.gaps[2].filled);
}

// A group whose fill throws leaves its gaps open with the error, and the other groups fill.
TEST(PerGapFill, AFailingGroupSaysWhyAndTheOthersFill)
{
  Take take = movingTake();
  const Gap linear = hide(take, 0, 30, 4);
  const Gap spline = hide(take, 1, 30, 4);
  FillOptions rules;
  rules.maxGap = -1;  // options fillGaps refuses
  const FillResult refused =
      fillEachGap(take, {linear, spline}, {FillMethod::Linear, FillMethod::Spline}, {false, true}, rules);
  ASSERT_EQ(refused.gaps.size(), 2u);
  EXPECT_FALSE(refused.gaps[0].filled);
  EXPECT_EQ(refused.gaps[0].cause, UnfilledCause::Method);
  EXPECT_FALSE(refused.gaps[0].reason.empty());
  EXPECT_EQ(refused.gaps[0].gap.marker, 0);
  EXPECT_TRUE(refused.gaps[1].filled);  // past the rules: maxGap lifted
}

TEST(PerGapFill, CancellingThrows)
{
  Take take = movingTake();
  const Gap gap = hide(take, 0, 30, 4);
  auto cancel = std::make_shared<std::atomic<bool>>(true);
  const JobControl job({}, cancel);
  EXPECT_THROW((void)fillEachGap(take, {gap}, {FillMethod::Linear}, {false}, FillOptions{}, job), JobCancelled);
}

TEST(FillRules, WithoutFillRulesKeepsTheMethodAndNeighbours)
{
  FillOptions options;
  options.method = FillMethod::Rigid;
  options.neighbours = 4;
  const FillOptions lifted = withoutFillRules(options);
  EXPECT_EQ(lifted.method, FillMethod::Rigid);
  EXPECT_EQ(lifted.neighbours, 4);
  EXPECT_EQ(lifted.maxGap, 0);
  EXPECT_EQ(lifted.maxGapSeconds, 0.0);
  EXPECT_TRUE(lifted.extrapolate);
  EXPECT_EQ(lifted.minValidFraction, 0.0);
}

TEST(FillRules, SameFillRulesComparesTheRulesOnly)
{
  FillOptions a;
  FillOptions b;
  b.method = FillMethod::Pca;
  b.neighbours = 3;
  EXPECT_TRUE(sameFillRules(a, b));
  for (int field = 0; field < 4; ++field) {
    FillOptions c = a;
    if (field == 0)
      c.maxGap = 7;
    else if (field == 1)
      c.maxGapSeconds = 1.0;
    else if (field == 2)
      c.extrapolate = true;
    else
      c.minValidFraction = 0.5;
    EXPECT_FALSE(sameFillRules(a, c)) << "field " << field;
  }
}

} // namespace
} // namespace mocap
