#include "nose_mocap_fixture.h"
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/tracking/swap_detection.h"
#include "mocap/io/take_io.h"
#include "mocap/evaluation/tracking_evaluation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace mocap {
namespace {

TEST(SwapDetection, FindsAndRepairsInjectedSwapsOfNeighbouringMarkers)
{
  const Take take = test::noseMoCapTake();
  for (const std::uint64_t seed : {1U, 2U, 3U}) {
    TrackingEvaluationOptions options;
    options.seed = seed;
    options.swaps = 8;
    std::vector<InjectedSwap> injected;
    Take swapped = makeSwappedCopy(take, options, injected);
    ASSERT_EQ(injected.size(), 8U);
    EXPECT_LT(labelAgreement(take, swapped, {}), 0.99);
    const std::vector<LabelSwap> found = repairSwaps(swapped);
    EXPECT_EQ(labelAgreement(take, swapped, {}), 1.0) << "seed " << seed;
    ASSERT_EQ(found.size(), 2 * injected.size());  // each swap and its swap back
    for (const InjectedSwap& swap : injected) {
      const auto at = [&](Eigen::Index frame) {
        return std::any_of(found.begin(), found.end(), [&](const LabelSwap& s) {
          return s.frame == frame && s.first == swap.first && s.second == swap.second;
        });
      };
      EXPECT_TRUE(at(swap.begin));
      EXPECT_TRUE(at(swap.end));
    }
  }
}

TEST(SwapDetection, ModelOutputsAreNeverSwappedOrFlagged)
{
  TrackingEvaluationOptions options;
  options.seed = 1;
  options.swaps = 8;
  std::vector<InjectedSwap> injected;
  Take swapped = makeSwappedCopy(test::noseMoCapTake(), options, injected);
  ASSERT_FALSE(injected.empty());
  // The first swapped marker is, in this take, a model output (an angle stored as a point).
  const Eigen::Index output = injected.front().first;
  swapped.setPointType(output, PointType::Angle);
  const Eigen::MatrixXd before = swapped.trajectory(output);
  EXPECT_FALSE(findJumps(swapped).col(output).any());
  const std::vector<LabelSwap> found = repairSwaps(swapped);
  EXPECT_FALSE(found.empty()) << "the other markers' swaps are still repaired";
  for (const LabelSwap& swap : found)
    EXPECT_TRUE(swap.first != output && swap.second != output) << "frame " << swap.frame;
  const Eigen::ArrayXXd after = swapped.trajectory(output);
  EXPECT_TRUE((after == before.array() || (after.isNaN() && before.array().isNaN())).all());
}

TEST(SwapDetection, DetectLeavesTheTakeAloneAndFindsNothingInACleanTake)
{
  const Take take = test::noseMoCapTake();
  EXPECT_TRUE(detectSwaps(take).empty());
  TrackingEvaluationOptions options;
  std::vector<InjectedSwap> injected;
  const Take swapped = makeSwappedCopy(take, options, injected);
  const Take before = swapped;
  EXPECT_EQ(detectSwaps(swapped).size(), 2 * injected.size());
  EXPECT_EQ(labelAgreement(before, swapped, {}), 1.0);
}

TEST(SwapDetection, ExchangingTwiceRestoresTheTake)
{
  const Take take = test::noseMoCapTake();
  Take copy = take;
  copy.setState(500, 3, SampleOrigin::Edited);
  const Take edited = copy;
  exchangeMarkersFrom(copy, 3, 9, 400);
  EXPECT_EQ(copy.position(600, 3), take.position(600, 9));
  EXPECT_EQ(copy.state(500, 9), SampleOrigin::Edited);
  EXPECT_EQ(copy.position(399, 3), take.position(399, 3));
  exchangeMarkersFrom(copy, 3, 9, 400);
  EXPECT_EQ(labelAgreement(edited, copy, {}), 1.0);
  EXPECT_EQ(copy.state(500, 3), SampleOrigin::Edited);
  EXPECT_THROW(exchangeMarkersFrom(copy, 3, copy.markerCount(), 0), InvalidArgument);
}

TEST(SwapDetection, RejectsOptionsOutOfRange)
{
  Take take = test::noseMoCapTake();
  SwapOptions options;
  options.jumpFactor = 1.0;
  EXPECT_THROW((void)repairSwaps(take, options), InvalidArgument);
  options = {};
  options.swappedFraction = 1.0;
  EXPECT_THROW((void)repairSwaps(take, options), InvalidArgument);
  options = {};
  options.minJump = std::nan("");
  EXPECT_THROW((void)repairSwaps(take, options), InvalidArgument);
  Take empty;
  EXPECT_TRUE(repairSwaps(empty).empty());
}

} // namespace
} // namespace mocap
