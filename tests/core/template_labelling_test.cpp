#include "nose_mocap_fixture.h"
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/tracking/fragment_joining.h"
#include "mocap/io/take_io.h"
#include "mocap/tracking/template_labelling.h"
#include "mocap/evaluation/tracking_evaluation.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace mocap {
namespace {

PointSet randomPoints(Eigen::Index n)
{
  std::srand(3);
  return PointSet::Random(n, 3) * 50.0;
}

TEST(TemplateLabelling, LooseSimilarityFitDegradesGracefullyOnFewPoints)
{
  // The exact fit is tested with the mesh binding (similarity_transform.h); labelling needs the
  // loose one for neighbourhoods of one or two markers.
  const PointSet one = PointSet::Constant(1, 3, 2.0);
  const Similarity shift = fitSimilarityLoose(one, one.array() + 3.0);
  EXPECT_EQ(shift.scale, 1.0);
  EXPECT_TRUE(shift.rotation.isIdentity());
  EXPECT_LT((shift.translation - Eigen::Vector3d::Constant(3.0)).norm(), 1e-12);
  const PointSet same = PointSet::Ones(4, 3);
  EXPECT_EQ(fitSimilarityLoose(same, randomPoints(4)).scale, 1.0) << "coincident points: no scale to find";
  EXPECT_THROW((void)fitSimilarity(one, one), InvalidArgument) << "the strict fit needs three points";
  EXPECT_THROW((void)fitSimilarityLoose(PointSet(0, 3), PointSet(0, 3)), InvalidArgument);
  EXPECT_THROW((void)fitSimilarityLoose(one, same), InvalidArgument);
}

TEST(TemplateLabelling, AlignsATemplateToShuffledMovedPointsWithoutCorrespondences)
{
  const Take take = test::noseMoCapTake();
  const MarkerSet set = markerSetFromTake(take);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitY()).toRotationMatrix();
  PointSet moved(set.size(), 3);
  for (Eigen::Index i = 0; i < set.size(); ++i)  // reversed order: no correspondence by index
    moved.row(set.size() - 1 - i) = (rotation * set.neutral.row(i).transpose() + Eigen::Vector3d(40, 10, -30)).transpose();
  double residual = -1.0;
  const Similarity s = alignTemplate(set.neutral, moved.topRows(set.size() - 4), &residual);  // four points missing
  EXPECT_LT(residual, 1e-6);
  for (Eigen::Index i = 4; i < set.size(); ++i)
    EXPECT_LT((s.apply(set.neutral.row(i).transpose()) - moved.row(set.size() - 1 - i).transpose()).norm(), 1e-6);
}

TEST(TemplateLabelling, RecoversTheLabelsOfAFragmentedUnlabelledTake)
{
  const Take take = test::noseMoCapTake();
  TrackingEvaluationOptions options;
  options.seed = 4;
  const UnlabelledCopy copy = makeUnlabelledCopy(take, options);
  ASSERT_GT(copy.fragments, 100);
  for (const bool retrack : {true, false}) {
    TrackOptions track;
    track.retrack = retrack;
    // A template moved rigidly away from the data: the labeller must find the alignment itself.
    MarkerSet set = markerSetFromTake(take);
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (Eigen::Index i = 0; i < set.size(); ++i)
      set.neutral.row(i) = (turn * set.neutral.row(i).transpose() + Eigen::Vector3d(300, 0, 0)).transpose();
    TrackReport report;
    const Take labelled = trackTake(copy.take, &set, track, &report);
    EXPECT_GE(labelAgreement(take, labelled, copy.kept), 0.995) << "retrack " << retrack;
    EXPECT_EQ(report.labelledSamples + report.unlabelledSamples, copy.kept.count());
    for (Eigen::Index m = 0; m < set.size(); ++m)
      EXPECT_EQ(labelled.label(m), set.labels[static_cast<std::size_t>(m)]);
  }
}

TEST(TemplateLabelling, JoinsAnUnlabelledFragmentIntoTheGapItFills)
{
  Take take = test::noseMoCapTake();
  const Take truth = take;
  const Eigen::Index marker = 7;
  const Eigen::Index stray = take.addMarker("Unlabeled1");
  for (Eigen::Index f = 300; f < 420; ++f) {  // move a stretch of the marker to an unlabelled one
    take.setPosition(f, stray, take.position(f, marker));
    take.valid()(f, stray) = take.isValid(f, marker);
    take.residuals()(f, stray) = 0.0;
    take.valid()(f, marker) = false;
  }
  TrackOptions options;
  options.retrack = false;
  TrackReport report;
  const Take joined = trackTake(take, nullptr, options, &report);
  EXPECT_EQ(joined.markerCount(), truth.markerCount());  // nothing left unlabelled
  EXPECT_EQ(report.unlabelledFragments, 0);
  EXPECT_EQ(labelAgreement(truth, joined, {}), 1.0);
}

TEST(TemplateLabelling, RejectsBadOptions)
{
  Take take = test::noseMoCapTake();
  const MarkerSet set = markerSetFromTake(take);
  LabellingOptions options;
  options.gateFactor = 0.0;
  EXPECT_THROW((void)labelFragments(take, {}, set, options), InvalidArgument);
  options = {};
  options.neighbours = 2;
  EXPECT_THROW((void)labelFragments(take, {}, set, options), InvalidArgument);
  Fragment outside;
  outside.first = take.frameCount();
  outside.positions.emplace_back(0, 0, 0);
  EXPECT_THROW((void)labelFragments(take, {outside}, set), InvalidArgument);
}

} // namespace
} // namespace mocap
