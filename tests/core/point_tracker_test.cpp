#include "mocap/base/error.h"
#include "mocap/base/random.h"
#include "mocap/tracking/point_tracker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace mocap {
namespace {

constexpr Eigen::Index kMarkers = 12;
constexpr Eigen::Index kFrames = 400;

// Marker m at frame f: a grid 30 mm apart, each marker on its own smooth path of up to 8 mm.
Eigen::Vector3d truePosition(Eigen::Index m, Eigen::Index f)
{
  const double t = static_cast<double>(f) / 100.0;
  const double phase = static_cast<double>(m);
  return {30.0 * static_cast<double>(m % 4) + 8.0 * std::sin(2.0 * t + phase),
          30.0 * static_cast<double>(m / 4) + 8.0 * std::cos(1.3 * t + phase), 5.0 * std::sin(0.7 * t)};
}

// The markers as unlabelled points, shuffled in every frame; `hidden(m, f)` drops a point.
template <typename Hidden>
PointCloud shuffledCloud(Hidden hidden, std::uint64_t seed)
{
  PointCloud cloud;
  Random random(seed);
  for (Eigen::Index f = 0; f < kFrames; ++f) {
    std::vector<Eigen::Vector3d> frame;
    for (Eigen::Index m = 0; m < kMarkers; ++m)
      if (!hidden(m, f))
        frame.push_back(truePosition(m, f));
    random.shuffle(frame.begin(), frame.end());
    cloud.points.insert(cloud.points.end(), frame.begin(), frame.end());
    cloud.frameStart.push_back(static_cast<Eigen::Index>(cloud.points.size()));
  }
  return cloud;
}

// The marker a fragment follows, or −1 when it mixes markers.
Eigen::Index followedMarker(const Fragment& fragment)
{
  for (Eigen::Index m = 0; m < kMarkers; ++m) {
    bool all = true;
    for (Eigen::Index f = fragment.first; all && f <= fragment.last(); ++f)
      all = (fragment.at(f) - truePosition(m, f)).norm() < 1e-12;
    if (all)
      return m;
  }
  return -1;
}

TEST(PointTracker, LinksShuffledPointsIntoOneTrajectoryPerMarker)
{
  const PointCloud cloud = shuffledCloud([](Eigen::Index, Eigen::Index) { return false; }, 3);
  for (const MotionModel model : {MotionModel::ConstantVelocity, MotionModel::ConstantAcceleration}) {
    TrackerOptions options;
    options.model = model;
    const TrackingResult result = trackPoints(cloud, options);
    ASSERT_EQ(static_cast<Eigen::Index>(result.fragments.size()), kMarkers);
    std::vector<bool> seen(kMarkers, false);
    for (const Fragment& fragment : result.fragments) {
      EXPECT_EQ(fragment.first, 0);
      EXPECT_EQ(fragment.length(), kFrames);
      const Eigen::Index m = followedMarker(fragment);
      ASSERT_GE(m, 0);
      EXPECT_FALSE(seen[static_cast<std::size_t>(m)]);
      seen[static_cast<std::size_t>(m)] = true;
    }
    EXPECT_GT(result.gate, 5.0);   // half the 30 mm spacing, less the motion
    EXPECT_LT(result.gate, 15.0);
  }
}

TEST(PointTracker, AVanishingPointEndsItsFragmentAndStartsANewOne)
{
  const auto hidden = [](Eigen::Index m, Eigen::Index f) { return (m == 5 && f >= 100 && f < 120) || (m == 2 && f < 10); };
  const TrackingResult result = trackPoints(shuffledCloud(hidden, 11));
  ASSERT_EQ(static_cast<Eigen::Index>(result.fragments.size()), kMarkers + 1);
  Eigen::Index samples = 0;
  for (const Fragment& fragment : result.fragments) {
    EXPECT_GE(followedMarker(fragment), 0) << "a fragment mixes markers";
    samples += fragment.length();
    for (Eigen::Index f = fragment.first; f <= fragment.last(); ++f)
      EXPECT_FALSE(hidden(followedMarker(fragment), f));
  }
  EXPECT_EQ(samples, kMarkers * kFrames - 20 - 10);
}

TEST(PointTracker, GateBelowTheMotionSplitsEveryFrame)
{
  TrackerOptions options;
  options.maxSpeed = 1e-6;
  const TrackingResult result = trackPoints(shuffledCloud([](Eigen::Index, Eigen::Index) { return false; }, 5), options);
  EXPECT_EQ(static_cast<Eigen::Index>(result.fragments.size()), kMarkers * kFrames);
}

TEST(PointTracker, RejectsBadOptionsAndPoints)
{
  PointCloud cloud = shuffledCloud([](Eigen::Index, Eigen::Index) { return false; }, 1);
  TrackerOptions options;
  options.maxSpeed = -1.0;
  EXPECT_THROW((void)trackPoints(cloud, options), InvalidArgument);
  options.maxSpeed = std::nan("");
  EXPECT_THROW((void)trackPoints(cloud, options), InvalidArgument);
  cloud.points[5].x() = std::nan("");
  EXPECT_THROW((void)trackPoints(cloud), InvalidArgument);
  EXPECT_TRUE(trackPoints(PointCloud{}).fragments.empty());
}

TEST(PointCloudCsv, ReadsFramesInAnyOrderWithHeaderAndComments)
{
  const PointCloud cloud = parsePointCloudCsv("frame,x,y,z\n# a comment\n12,1,2,3\n10,4,5,6\n\n12,7,8,9\n", "p.csv");
  ASSERT_EQ(cloud.frameCount(), 3);
  EXPECT_EQ(cloud.pointCount(0), 1);
  EXPECT_EQ(cloud.pointCount(1), 0);
  EXPECT_EQ(cloud.pointCount(2), 2);
  EXPECT_EQ(cloud.point(0, 0), Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(cloud.point(2, 1), Eigen::Vector3d(7, 8, 9));
}

TEST(PointCloudCsv, BadLinesNameTheirLine)
{
  try {
    (void)parsePointCloudCsv("0,1,2,3\n1,2,x,4\n", "p.csv");
    FAIL() << "no error";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)parsePointCloudCsv("0,1,2\n", "p.csv"), FormatError);
  EXPECT_THROW((void)parsePointCloudCsv("0.5,1,2,3\n", "p.csv"), FormatError);
  EXPECT_THROW((void)parsePointCloudCsv("0,1,2,nan\n", "p.csv"), FormatError);
  EXPECT_THROW((void)parsePointCloudCsv("0,1,2,3\n999999999,1,2,3\n", "p.csv"), FormatError);
}

} // namespace
} // namespace mocap
