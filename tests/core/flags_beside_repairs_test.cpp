#include "foreign_takes.h"

#include "mocap/cleaning/flags_beside_repairs.h"
#include "mocap/model/sample_patch.h"

#include <gtest/gtest.h>

namespace mocap {
namespace {

// A repair of `marker` at `frames` to (f, marker, 1), applied to `take`.
SamplePatch repair(Take& take, Eigen::Index marker, std::vector<Eigen::Index> frames)
{
  Eigen::Matrix<double, Eigen::Dynamic, 3> positions(static_cast<Eigen::Index>(frames.size()), 3);
  for (std::size_t i = 0; i < frames.size(); ++i)
    positions.row(static_cast<Eigen::Index>(i)) << static_cast<double>(frames[i]), static_cast<double>(marker), 1.0;
  SamplePatch patch = makePatch(marker, std::move(frames), std::move(positions), SampleOrigin::Edited);
  (void)swapSamples(take, patch);
  return patch;
}

TEST(FlagsBesideRepairs, NothingGivenIsNone)
{
  Take take = test::distinctValuesTake(2, 20);
  EXPECT_EQ(flagsBesideRepairs(take, {}, {}), 0u);
  EXPECT_EQ(flagsBesideRepairs(take, {{0, 5}}, {}), 0u);
  const SamplePatch repaired = repair(take, 0, {5});
  EXPECT_EQ(flagsBesideRepairs(take, {}, {repaired}), 0u);
}

TEST(FlagsBesideRepairs, CountsFlagsWithinTwoFramesOfTheSameMarker)
{
  Take take = test::distinctValuesTake(2, 20);
  const SamplePatch repaired = repair(take, 0, {10});
  // Beside: frames 8..12 of marker a. Not beside: frame 7 and 13, and marker b at frame 10.
  const std::vector<SpikeFlag> flags{{0, 7}, {0, 8}, {0, 10}, {0, 12}, {0, 13}, {1, 10}};
  EXPECT_EQ(flagsBesideRepairs(take, flags, {repaired}), 3u);
}

TEST(FlagsBesideRepairs, AnUndoneRepairDoesNotCount)
{
  Take take = test::distinctValuesTake(2, 20);
  SamplePatch repaired = repair(take, 1, {4, 5});
  const std::vector<SpikeFlag> flags{{1, 6}};
  EXPECT_EQ(flagsBesideRepairs(take, flags, {repaired}), 1u);
  Take undone = test::distinctValuesTake(2, 20);
  EXPECT_EQ(flagsBesideRepairs(undone, flags, {repaired}), 0u);
  undone.valid()(5, 1) = false;  // deleted since: no longer repaired either
  EXPECT_EQ(flagsBesideRepairs(undone, flags, {repaired}), 0u);
}

// The repairs may be older than the take: a marker or frame the take no longer has is skipped.
TEST(FlagsBesideRepairs, RepairsOutsideTheTakeAreSkipped)
{
  Take take = test::distinctValuesTake(2, 20);
  SamplePatch gone = repair(take, 1, {18});
  gone.marker = 5;
  SamplePatch late = repair(take, 0, {19});
  late.frames = {25};
  EXPECT_EQ(flagsBesideRepairs(take, {{0, 19}, {1, 18}}, {gone, late}), 0u);
}

} // namespace
} // namespace mocap
