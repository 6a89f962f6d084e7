#include "mocap/base/error.h"
#include "mocap/model/gaps.h"
#include "mocap/model/take.h"

#include <gtest/gtest.h>

namespace mocap {
namespace {

TEST(Take, TrajectoryIsAContiguousViewOfOneMarker)
{
  Take take({"a", "b"}, 5, 60.0);
  take.setPosition(3, 1, {1.0, 2.0, 3.0});
  auto trajectory = take.trajectory(1);
  EXPECT_EQ(trajectory.rows(), 5);
  EXPECT_EQ(trajectory(3, 2), 3.0);
  trajectory(4, 0) = 7.5;
  EXPECT_EQ(take.position(4, 1).x(), 7.5);
  EXPECT_EQ(take.trajectory(0).data() + 15, take.trajectory(1).data());
  EXPECT_FALSE(take.valid().any()) << "a new take has no valid samples; gaps are never zeros";
}

TEST(Take, LabelsAreUnique)
{
  std::vector<std::string> labels{"a", "a", "", "a_2"};
  const auto warnings = makeLabelsUnique(labels);
  EXPECT_EQ(labels, (std::vector<std::string>{"a", "a_2", "M3", "a_2_2"}));
  EXPECT_EQ(warnings.size(), 3u);
  Take take({"x", "y"}, 1, 100.0);
  EXPECT_THROW(take.setLabel(0, "y"), InvalidArgument);
  EXPECT_THROW(take.setLabel(0, ""), InvalidArgument);
  take.setLabel(0, "z");
  EXPECT_EQ(take.markerIndex("z"), 0);
  EXPECT_EQ(take.markerIndex("x"), std::nullopt);
}

TEST(Take, RejectsAbsurdArguments)
{
  EXPECT_THROW(Take({"a"}, 10, 0.0), InvalidArgument);
  EXPECT_THROW(Take({"a"}, 10, std::nan("")), InvalidArgument);
  EXPECT_THROW(Take({"a"}, -1, 100.0), InvalidArgument);
  Take take({"a"}, 10, 100.0);
  EXPECT_THROW((void)take.position(10, 0), InvalidArgument);
  EXPECT_THROW((void)take.trajectory(1), InvalidArgument);
}

TEST(Take, UnitConversionScalesPositionsAndValidResiduals)
{
  Take take({"a"}, 2, 100.0);
  take.setPosition(0, 0, {1000.0, -20.0, 3.0});
  take.valid()(0, 0) = true;
  take.residuals()(0, 0) = 2.0;
  take.convertUnits(LengthUnit::Metre);
  EXPECT_EQ(take.units(), LengthUnit::Metre);
  EXPECT_DOUBLE_EQ(take.position(0, 0).x(), 1.0);
  EXPECT_DOUBLE_EQ(take.residuals()(0, 0), 0.002);
  EXPECT_EQ(take.residuals()(1, 0), -1.0);
  take.convertUnits(LengthUnit::Centimetre);
  EXPECT_DOUBLE_EQ(take.position(0, 0).y(), -2.0);
}

TEST(Take, AddMarkerKeepsExistingData)
{
  Take take({"a"}, 3, 100.0);
  take.setPosition(2, 0, {1, 2, 3});
  take.valid()(2, 0) = true;
  take.setState(2, 0, SampleOrigin::Filled);
  EXPECT_EQ(take.addMarker("a"), 1);
  EXPECT_EQ(take.label(1), "a_2");
  EXPECT_EQ(take.position(2, 0), Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(take.isValid(2, 0));
  EXPECT_FALSE(take.valid().col(1).any());
  EXPECT_EQ(take.state(2, 0), SampleOrigin::Filled);
}

TEST(Gaps, RunsOfInvalidSamplesWithEdges)
{
  ValidMask valid(10);
  valid << false, true, true, false, false, true, true, true, false, false;
  const auto gaps = findGaps(valid, 4);
  ASSERT_EQ(gaps.size(), 3u);
  EXPECT_EQ(gaps[0].firstFrame, 0);
  EXPECT_EQ(gaps[0].length, 1);
  EXPECT_TRUE(gaps[0].atEdge);
  EXPECT_EQ(gaps[1].firstFrame, 3);
  EXPECT_EQ(gaps[1].length, 2);
  EXPECT_FALSE(gaps[1].atEdge);
  EXPECT_EQ(gaps[2].length, 2);
  EXPECT_TRUE(gaps[2].atEdge);
  EXPECT_EQ(gaps[2].marker, 4);
}

} // namespace
} // namespace mocap
