#include "test_support.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/base/error.h"
#include "mocap/model/sample_patch.h"

#include <gtest/gtest.h>

namespace mocap {
namespace {

TEST(SamplePatch, SwapThenSwapBackRestoresTheTakeBitForBit)
{
  Take take = readC3d(test::sampleTake());
  const Take original = take;
  const auto marker = *take.markerIndex("section3-1");
  std::vector<Eigen::Index> frames;
  for (Eigen::Index f = 880; f < 925; ++f)
    frames.push_back(f);
  Eigen::Matrix<double, Eigen::Dynamic, 3> positions(45, 3);
  positions.setConstant(1.5);
  SamplePatch undo = swapSamples(take, makePatch(marker, frames, positions, SampleOrigin::Filled));
  EXPECT_TRUE(take.valid().col(marker).segment(880, 45).all());
  EXPECT_EQ(take.state(900, marker), SampleOrigin::Filled);
  EXPECT_EQ(take.position(900, marker), Eigen::Vector3d::Constant(1.5));
  const SamplePatch redo = swapSamples(take, std::move(undo));
  EXPECT_TRUE((take.valid() == original.valid()).all());
  EXPECT_TRUE((take.residuals() == original.residuals()).all());
  EXPECT_TRUE((take.states() == original.states()).all());
  for (Eigen::Index f = 0; f < take.frameCount(); ++f)
    ASSERT_EQ(take.position(f, marker), original.position(f, marker));
  EXPECT_EQ(redo.positions(20, 0), 1.5);
}

TEST(SamplePatch, ApplyPatchesReturnsUndoInReverseOrder)
{
  Take take({"a", "b"}, 4, 100.0);
  std::vector<SamplePatch> patches;
  patches.push_back(makePatch(0, {1}, Eigen::RowVector3d(1, 1, 1), SampleOrigin::Edited));
  patches.push_back(makePatch(0, {1}, Eigen::RowVector3d(2, 2, 2), SampleState().with(SampleOperation::Smoothed)));
  auto undo = applyPatches(take, std::move(patches));
  EXPECT_EQ(take.position(1, 0), Eigen::Vector3d(2, 2, 2));
  applyPatches(take, std::move(undo));
  EXPECT_FALSE(take.isValid(1, 0));
  EXPECT_EQ(take.position(1, 0), Eigen::Vector3d::Zero());
  EXPECT_EQ(take.state(1, 0), SampleOrigin::Measured);
}

TEST(SamplePatch, DeleteSamplesMakesAGapAndUndoBringsItBack)
{
  Take take = readC3d(test::sampleTake());
  const Take original = take;
  const auto marker = *take.markerIndex("section3-1");
  SamplePatch patch = deleteSamples(take, marker, 880, 925);
  EXPECT_EQ(patch.size(), 46u - 33u) << "frames 887-919 were already a gap";
  SamplePatch undo = swapSamples(take, std::move(patch));
  EXPECT_FALSE(take.valid().col(marker).segment(880, 46).any());
  EXPECT_EQ(take.residuals()(880, marker), -1.0);
  EXPECT_EQ(take.state(880, marker), SampleOrigin::Edited);
  swapSamples(take, std::move(undo));
  EXPECT_TRUE((take.valid() == original.valid()).all());
  EXPECT_TRUE((take.residuals() == original.residuals()).all());
  EXPECT_THROW((void)deleteSamples(take, marker, 10, 5), InvalidArgument);
  EXPECT_THROW((void)deleteSamples(take, marker, 0, 3000), InvalidArgument);
}

TEST(SamplePatch, MisfitPatchesAreRejectedWithoutChanges)
{
  Take take({"a"}, 4, 100.0);
  EXPECT_THROW(swapSamples(take, makePatch(1, {0}, Eigen::RowVector3d(1, 1, 1), SampleOrigin::Edited)), InvalidArgument);
  EXPECT_THROW(swapSamples(take, makePatch(0, {4}, Eigen::RowVector3d(1, 1, 1), SampleOrigin::Edited)), InvalidArgument);
  Eigen::Matrix<double, Eigen::Dynamic, 3> two(2, 3);
  two.setOnes();
  EXPECT_THROW(swapSamples(take, makePatch(0, {2, 1}, two, SampleOrigin::Edited)), InvalidArgument);
  EXPECT_THROW((void)makePatch(0, {1}, two, SampleOrigin::Edited), InvalidArgument);
  EXPECT_FALSE(take.valid().any());
}

TEST(SamplePatch, PatchWithinKeepsOnlyTheFramesOfTheRange)
{
  Eigen::Matrix<double, Eigen::Dynamic, 3> positions(4, 3);
  positions << 1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4;
  const SamplePatch patch = makePatch(2, {3, 5, 7, 9}, positions, SampleOrigin::Filled);
  const SamplePatch part = patchWithin(patch, 4, 7);
  EXPECT_EQ(part.marker, 2);
  EXPECT_EQ(part.frames, (std::vector<Eigen::Index>{5, 7}));
  EXPECT_EQ(part.positions.row(0), Eigen::RowVector3d(2, 2, 2));
  EXPECT_EQ(part.positions.row(1), Eigen::RowVector3d(3, 3, 3));
  EXPECT_EQ(part.valid.size(), 2);
  EXPECT_EQ(part.residuals.size(), 2);
  EXPECT_EQ(part.states.size(), 2u);
  EXPECT_TRUE(patchWithin(patch, 10, 20).empty());
  EXPECT_TRUE(patchWithin(patch, 5, 4).empty());
}

} // namespace
} // namespace mocap
