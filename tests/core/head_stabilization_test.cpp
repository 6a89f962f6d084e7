#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/cleaning/head_marker_labels.h"
#include "mocap/cleaning/head_stabilization.h"
#include "mocap/io/take_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace mocap {
namespace {

// Per-axis standard deviation of a marker's valid samples.
Eigen::Vector3d deviation(const Take& take, Eigen::Index marker)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Vector3d squares = Eigen::Vector3d::Zero();
  double count = 0.0;
  for (Eigen::Index f = 0; f < take.frameCount(); ++f)
    if (take.isValid(f, marker)) {
      const Eigen::Vector3d p = take.position(f, marker);
      sum += p;
      squares += p.cwiseProduct(p);
      count += 1.0;
    }
  return (squares / count - (sum / count).cwiseProduct(sum / count)).cwiseMax(0.0).cwiseSqrt();
}

// A head (4 rigid markers) and a cheek marker, turning and moving over 50 frames.
Take movingHead()
{
  Take take({"h1", "h2", "h3", "h4", "cheek"}, 50, 100.0);
  const Eigen::Matrix<double, 5, 3> shape =
      (Eigen::Matrix<double, 5, 3>() << 0, 0, 0, 80, 0, 0, 0, 90, 10, 40, 40, 70, 30, -60, 40).finished();
  for (Eigen::Index f = 0; f < 50; ++f) {
    const double t = 0.02 * static_cast<double>(f);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::AngleAxisd(0.6 * std::sin(3 * t), Eigen::Vector3d(0.2, 1, 0.1).normalized())
                        .toRotationMatrix();
    pose.translation() = Eigen::Vector3d(20 * t, 5 * std::cos(t), 1000);
    for (Eigen::Index m = 0; m < 5; ++m) {
      Eigen::Vector3d local = shape.row(m).transpose();
      if (m == 4)
        local.y() += 3.0 * std::sin(5 * t);  // the face moves on the head
      take.setPosition(f, m, pose * local);
      take.valid()(f, m) = true;
    }
  }
  return take;
}

TEST(HeadStabilization, RemovesRigidHeadMotionAndRestoresItExactly)
{
  Take take = movingHead();
  const Take original = take;
  const HeadMotion motion = estimateHeadMotion(take, {0, 1, 2, 3});
  EXPECT_EQ(motion.referenceFrame, 0);
  ASSERT_EQ(motion.poses.size(), 50u);
  removeHeadMotion(take, motion);
  for (Eigen::Index m = 0; m < 4; ++m)
    for (Eigen::Index f = 0; f < 50; ++f)
      EXPECT_LT((take.position(f, m) - original.position(0, m)).norm(), 1e-9);
  EXPECT_LT(deviation(take, 4).x(), 1e-9);  // only the facial motion (along y) is left
  EXPECT_GT(deviation(take, 4).y(), 1.0);
  restoreHeadMotion(take, motion);
  for (Eigen::Index m = 0; m < 5; ++m)
    for (Eigen::Index f = 0; f < 50; ++f)
      ASSERT_LT((take.position(f, m) - original.position(f, m)).norm(), 1e-9);
  EXPECT_TRUE((take.valid() == original.valid()).all());
}

TEST(HeadStabilization, PatchesMoveTheSamplesAsRemoveHeadMotionDoesAndKeepTheirValidity)
{
  Take take = movingHead();
  take.valid()(7, 4) = false;
  take.setState(9, 4, SampleOrigin::Filled);
  const HeadMotion motion = estimateHeadMotion(take, {0, 1, 2, 3});
  Take expected = take;
  removeHeadMotion(expected, motion);
  Take patched = take;
  const std::vector<SamplePatch> undo = applyPatches(patched, headMotionRemovalPatches(take, motion));
  for (Eigen::Index m = 0; m < 5; ++m)
    for (Eigen::Index f = 0; f < 50; ++f)
      ASSERT_EQ(patched.position(f, m), expected.position(f, m)) << m << " " << f;
  EXPECT_TRUE((patched.valid() == take.valid()).all());
  // The samples keep their origin and say they were stabilized (a gap has nothing to say).
  EXPECT_EQ(patched.state(9, 4), SampleState(SampleOrigin::Filled).with(SampleOperation::Stabilized));
  EXPECT_EQ(patched.state(8, 4), SampleState().with(SampleOperation::Stabilized));
  EXPECT_EQ(patched.state(7, 4), SampleOrigin::Measured);
  EXPECT_TRUE((std::as_const(patched).states() == std::as_const(expected).states()).all());
  applyPatches(patched, undo);
  for (Eigen::Index m = 0; m < 5; ++m)
    EXPECT_TRUE(patched.trajectory(m) == take.trajectory(m)) << "undo restores bit for bit";
  EXPECT_TRUE((std::as_const(patched).states() == std::as_const(take).states()).all());
  // Putting the head motion back takes the mark away again; the origin stays.
  restoreHeadMotion(expected, motion);
  EXPECT_EQ(expected.state(9, 4), SampleOrigin::Filled);
  EXPECT_EQ(expected.state(8, 4), SampleOrigin::Measured);
}

TEST(HeadStabilization, HeadMarkersAreGuessedFromTheirLabels)
{
  Take take({"Root-1", "nose", "HEAD_L", "header", "rootless", "chin"}, 1, 100.0);
  EXPECT_EQ(guessHeadReferenceMarkers(take), (std::vector<Eigen::Index>{0, 2, 3, 4}));
  EXPECT_TRUE(guessHeadReferenceMarkers(Take({"a", "b"}, 1, 100.0)).empty());
  EXPECT_EQ(labelledHeadMarkers(take), (std::vector<Eigen::Index>{0, 2, 3, 4}));
  // Labels name head markers; a rigid cluster is only a guess, which labelledHeadMarkers never makes.
  EXPECT_TRUE(labelledHeadMarkers(movingHead()).empty());
}

TEST(HeadStabilization, UnnamedHeadMarkersAreGuessedAsTheMostRigidCluster)
{
  // h1…h4 are not named like head markers: the rigid body they form gives them away, and the
  // cheek, which moves on the head by a few millimetres, is not part of it.
  const Take take = movingHead();
  EXPECT_EQ(guessHeadReferenceMarkers(take), (std::vector<Eigen::Index>{0, 1, 2, 3}));
  EXPECT_EQ(mostRigidCluster(take), (std::vector<Eigen::Index>{0, 1, 2, 3}));
  // A marker missing in most frames cannot be a head marker.
  Take sparse = take;
  sparse.valid().col(2).segment(0, 30).setConstant(false);
  EXPECT_EQ(mostRigidCluster(sparse), (std::vector<Eigen::Index>{0, 1, 3}));
  // Two rigid markers are no pose.
  Take twoRigid = take;
  twoRigid.valid().col(2).setConstant(false);
  twoRigid.valid().col(3).setConstant(false);
  EXPECT_TRUE(mostRigidCluster(twoRigid).empty());
  EXPECT_THROW((void)mostRigidCluster(take, RigidClusterOptions{0.0, 300}), InvalidArgument);
}

TEST(HeadStabilization, TheSampleHeadMarkersAreFoundWithoutTheirNames)
{
  Take take = readTake(test::sampleTake());
  std::vector<Eigen::Index> roots;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    if (take.label(m).rfind("root-", 0) == 0) {
      roots.push_back(m);
      take.setLabel(m, "marker" + std::to_string(m));
    }
  ASSERT_EQ(roots.size(), 6u);
  // Head markers only, enough for a pose: the headband's root-1…4 hold within 0.5 % strain, while
  // root-5 and root-6 (up to 1.5 %) are left for the user to add.
  const std::vector<Eigen::Index> guess = guessHeadReferenceMarkers(take);
  EXPECT_GE(guess.size(), 3u);
  for (const Eigen::Index m : guess)
    EXPECT_NE(std::find(roots.begin(), roots.end(), m), roots.end()) << take.label(m) << " is no head marker";
  EXPECT_NO_THROW((void)estimateHeadMotion(take, guess));
}

TEST(HeadStabilization, NoHeadIsProposedOnAFullBodyTake)
{
  // On Vicon's gait-pig the studio proposed the pelvis (LASI, RASI, LPSI, RPSI) as head markers:
  // the most rigid cluster of a body take is a pelvis or a limb's, and most markers are far from it.
  for (const char* file : {"c3d/sample03/gait-pig-nz.c3d", "c3d/sample00_motion_analysis/Walk1.c3d",
                           "c3d/btk_others/mocap36.c3d"}) {
    const Take take = readTake(test::dataFile(file));
    EXPECT_TRUE(headSizedRigidCluster(take).empty()) << file;
    EXPECT_TRUE(guessHeadReferenceMarkers(take).empty()) << file;
  }
  EXPECT_FALSE(mostRigidCluster(readTake(test::dataFile("c3d/sample03/gait-pig-nz.c3d"))).empty())
      << "the pelvis is rigid: the take, not the cluster, says it is no head";
  // A face take keeps its proposal, in any units.
  Take head = movingHead();
  EXPECT_EQ(headSizedRigidCluster(head), (std::vector<Eigen::Index>{0, 1, 2, 3}));
  head.convertUnits(LengthUnit::Metre);
  EXPECT_EQ(headSizedRigidCluster(head), (std::vector<Eigen::Index>{0, 1, 2, 3}));
}

TEST(HeadStabilization, HeadMarkersAreNamedBehindASubjectPrefix)
{
  // C3D files of other systems put the subject before every label (SUBJECTS:LABEL_PREFIXES):
  // Vicon's "Anna:root-1", ART's "Human3:HEAD".
  const Take take({"Anna:root-1", "Anna:nose", "Anna:HEAD_L", "Anna:root-2", "Tools:TOOL1", "rootless:chin"}, 1, 100.0);
  EXPECT_EQ(labelledHeadMarkers(take), (std::vector<Eigen::Index>{0, 2, 3}));
}

TEST(HeadStabilization, FramesWithTooFewReferenceMarkersAreInterpolated)
{
  Take take = movingHead();
  for (Eigen::Index f = 20; f < 25; ++f) {
    take.valid()(f, 0) = false;
    take.valid()(f, 1) = false;
  }
  take.valid()(49, 2) = false;
  take.valid()(49, 3) = false;
  const HeadMotion motion = estimateHeadMotion(take, {0, 1, 2, 3}, 5);
  EXPECT_EQ(motion.referenceFrame, 5);
  for (Eigen::Index f = 0; f < 50; ++f)
    EXPECT_EQ(motion.known[static_cast<std::size_t>(f)], (f < 20 || f >= 25) && f != 49) << f;
  // Smooth motion: the interpolated poses put the head within a millimetre of where it was
  // (it turns by 3° while those frames are missing).
  const Take truth = movingHead();
  for (Eigen::Index f = 20; f < 25; ++f)
    for (Eigen::Index m = 0; m < 4; ++m) {
      const Eigen::Vector3d head = motion.poses[static_cast<std::size_t>(f)] * truth.position(5, m);
      EXPECT_LT((head - truth.position(f, m)).norm(), 1.0) << f << " " << m;
    }
  EXPECT_TRUE(motion.poses[49].isApprox(motion.poses[48]));  // held after the last measured pose
}

TEST(HeadStabilization, FacialSingHeadMarkersBecomeStill)
{
  Take take = readTake(test::sampleTake());
  const Take original = take;
  std::vector<Eigen::Index> roots;
  for (int i = 1; i <= 6; ++i)
    roots.push_back(*take.markerIndex("root-" + std::to_string(i)));
  for (const Eigen::Index m : roots)
    EXPECT_GT(deviation(take, m).maxCoeff(), 10.0);  // the singer moves her head
  const HeadMotion motion = estimateHeadMotion(take, roots);
  removeHeadMotion(take, motion);
  // Head-mounted markers are rigid to 0.3-1.8 mm SD; stabilized, that is all that is left.
  for (const Eigen::Index m : roots)
    EXPECT_LE(deviation(take, m).maxCoeff(), 1.8) << take.label(m);
  restoreHeadMotion(take, motion);
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
      ASSERT_LT((take.position(f, m) - original.position(f, m)).norm(), 1e-9) << m << " " << f;
}

TEST(HeadStabilization, BadInputIsRejected)
{
  Take take = movingHead();
  EXPECT_THROW((void)estimateHeadMotion(take, {0, 1}), InvalidArgument);
  EXPECT_THROW((void)estimateHeadMotion(take, {0, 1, 1}), InvalidArgument);
  EXPECT_THROW((void)estimateHeadMotion(take, {0, 1, 9}), InvalidArgument);
  EXPECT_THROW((void)estimateHeadMotion(take, {0, 1, 2}, 50), InvalidArgument);
  EXPECT_THROW((void)estimateHeadMotion(take, {0, 1, 2}, -2), InvalidArgument);
  EXPECT_THROW((void)estimateHeadMotion(Take(), {0, 1, 2}), InvalidArgument);
  take.valid()(7, 2) = false;
  EXPECT_THROW((void)estimateHeadMotion(take, {0, 1, 2}, 7), InvalidArgument);
  Take never = movingHead();
  never.valid().col(2).setConstant(false);
  EXPECT_THROW((void)estimateHeadMotion(never, {0, 1, 2}), InvalidArgument);
  Take broken = movingHead();
  broken.setPosition(3, 1, Eigen::Vector3d::Constant(std::nan("")));
  EXPECT_THROW((void)estimateHeadMotion(broken, {0, 1, 2}), InvalidArgument);
  HeadMotion wrong = estimateHeadMotion(movingHead(), {0, 1, 2});
  wrong.poses.pop_back();
  EXPECT_THROW(removeHeadMotion(take, wrong), InvalidArgument);
  EXPECT_THROW(restoreHeadMotion(take, wrong), InvalidArgument);
}

} // namespace
} // namespace mocap
