#include "foreign_takes.h"

#include "mocap/base/error.h"
#include "mocap/cleaning/position_change.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mocap {
namespace {

// A patch moving `marker` at `frames` by the given offsets along x.
SamplePatch shifted(const Take& take, Eigen::Index marker, std::vector<Eigen::Index> frames,
                    const std::vector<double>& dx)
{
  Eigen::Matrix<double, Eigen::Dynamic, 3> positions(static_cast<Eigen::Index>(frames.size()), 3);
  for (std::size_t i = 0; i < frames.size(); ++i)
    positions.row(static_cast<Eigen::Index>(i)) =
        (take.position(frames[i], marker) + Eigen::Vector3d(dx[i], 0, 0)).transpose();
  return makePatch(marker, std::move(frames), std::move(positions), SampleOrigin::Edited);
}

TEST(PositionChange, NoPatchIsNoChange)
{
  const PositionChange change = positionChange(test::distinctValuesTake(2, 10), {});
  EXPECT_EQ(change.samples, 0);
  EXPECT_EQ(change.rms, 0.0);
  EXPECT_EQ(change.max, 0.0);
  EXPECT_EQ(change.maxMarker, -1);
}

TEST(PositionChange, RmsAndLargestMoveOverEveryPatch)
{
  const Take take = test::distinctValuesTake(2, 10);
  const PositionChange change =
      positionChange(take, {shifted(take, 0, {1, 2}, {3.0, 4.0}), shifted(take, 1, {5}, {-12.0})});
  EXPECT_EQ(change.samples, 3);
  EXPECT_DOUBLE_EQ(change.rms, std::sqrt((9.0 + 16.0 + 144.0) / 3.0));
  EXPECT_DOUBLE_EQ(change.max, 12.0);
  EXPECT_EQ(change.maxMarker, 1);
  EXPECT_EQ(change.maxFrame, 5);
}

TEST(PositionChange, OnlySamplesValidBeforeAndAfterCount)
{
  Take take = test::distinctValuesTake(2, 10);
  take.valid()(2, 0) = false;  // a gap the patch fills moves nothing
  SamplePatch patch = shifted(take, 0, {1, 2, 3}, {1.0, 50.0, 2.0});
  patch.valid(2) = false;  // nor does a sample the patch deletes
  const PositionChange change = positionChange(take, {patch});
  EXPECT_EQ(change.samples, 1);
  EXPECT_DOUBLE_EQ(change.max, 1.0);
  EXPECT_EQ(change.maxFrame, 1);
}

// A smoothing that moves nothing (still markers) still names a sample, so a summary can say
// where its (zero) largest move is.
TEST(PositionChange, NothingMovedStillNamesTheFirstSample)
{
  const Take take = test::distinctValuesTake(2, 10);
  const PositionChange change = positionChange(take, {shifted(take, 1, {4, 6}, {0.0, 0.0})});
  EXPECT_EQ(change.samples, 2);
  EXPECT_EQ(change.max, 0.0);
  EXPECT_EQ(change.maxMarker, 1);
  EXPECT_EQ(change.maxFrame, 4);
}

TEST(PositionChange, PatchOutsideTheTakeIsAClearError)
{
  const Take take = test::distinctValuesTake(2, 10);
  SamplePatch wrongMarker = shifted(take, 1, {0}, {1.0});
  wrongMarker.marker = 2;
  EXPECT_THROW((void)positionChange(take, {wrongMarker}), InvalidArgument);
  SamplePatch wrongFrame = shifted(take, 0, {9}, {1.0});
  wrongFrame.frames = {10};
  EXPECT_THROW((void)positionChange(take, {wrongFrame}), InvalidArgument);
  SamplePatch torn = shifted(take, 0, {3, 4}, {1.0, 1.0});
  torn.frames.pop_back();
  EXPECT_THROW((void)positionChange(take, {torn}), InvalidArgument);
}

} // namespace
} // namespace mocap
