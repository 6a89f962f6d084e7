// sliceFrames: the slice holds exactly the chosen frames of every per-sample array.
#include "mocap/base/error.h"
#include "mocap/model/take_slice.h"

#include <gtest/gtest.h>

namespace mocap {
namespace {

Take numberedTake()
{
  Take take({"a", "b"}, 10, 120.0);
  take.setFirstFrame(5);
  take.setUnits(LengthUnit::Centimetre);
  for (Eigen::Index m = 0; m < 2; ++m)
    for (Eigen::Index f = 0; f < 10; ++f) {
      const double x = static_cast<double>(f), y = static_cast<double>(m);
      take.setPosition(f, m, Eigen::Vector3d(x, 10.0 * y, -(x + y)));
      take.valid()(f, m) = (f + m) % 3 != 0;
      take.residuals()(f, m) = take.valid()(f, m) ? 0.1 * x : -1.0;
      take.setState(f, m, f % 2 ? SampleOrigin::Filled : SampleOrigin::Measured);
    }
  return take;
}

TEST(TakeSlice, KeepsTheChosenFramesAndRenumbersTheFirst)
{
  const Take take = numberedTake();
  const Take slice = sliceFrames(take, 3, 7);
  ASSERT_EQ(slice.frameCount(), 4);
  EXPECT_EQ(slice.labels(), take.labels());
  EXPECT_EQ(slice.firstFrame(), 8);
  EXPECT_EQ(slice.frameRate(), 120.0);
  EXPECT_EQ(slice.units(), LengthUnit::Centimetre);
  for (Eigen::Index m = 0; m < 2; ++m)
    for (Eigen::Index f = 0; f < 4; ++f) {
      EXPECT_EQ(slice.position(f, m), take.position(f + 3, m));
      EXPECT_EQ(slice.isValid(f, m), take.isValid(f + 3, m));
      EXPECT_EQ(slice.residuals()(f, m), take.residuals()(f + 3, m));
      EXPECT_EQ(slice.state(f, m), take.state(f + 3, m));
    }
}

TEST(TakeSlice, ARangeOutsideTheTakeIsRejected)
{
  const Take take = numberedTake();
  EXPECT_THROW((void)sliceFrames(take, -1, 3), InvalidArgument);
  EXPECT_THROW((void)sliceFrames(take, 4, 4), InvalidArgument);
  EXPECT_THROW((void)sliceFrames(take, 0, 11), InvalidArgument);
  EXPECT_EQ(sliceFrames(take, 0, 10).frameCount(), 10);
}

} // namespace
} // namespace mocap
