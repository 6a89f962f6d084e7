#include "nose_mocap_fixture.h"
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/evaluation/fill_evaluation.h"
#include "mocap/io/take_io.h"

#include <gtest/gtest.h>

#include <map>

namespace mocap {
namespace {

TEST(FillEvaluation, HiddenGapsFollowTheProtocol)
{
  Take take = test::noseMoCapTake();
  // A gap of the take's own: hidden gaps must avoid it, and count it in the quarter rule.
  for (Eigen::Index f = 300; f < 340; ++f)
    for (Eigen::Index m = 0; m < 8; ++m)
      take.valid()(f, m) = false;
  FillEvaluationOptions options;
  options.gapsPerCopy = 20;  // more than a quarter of 41: clamped to 10
  for (const Eigen::Index length : {10, 60, 240}) {
    for (int copy = 0; copy < 20; ++copy) {
      const auto gaps = evaluationGaps(take, length, copy, options);
      ASSERT_FALSE(gaps.empty());
      EXPECT_LE(gaps.size(), 10u);
      SampleMask hidden = SampleMask::Constant(take.frameCount(), take.markerCount(), false);
      Eigen::Index shared = 0;  // frames where several markers are missing at once
      for (const Gap& gap : gaps) {
        EXPECT_EQ(gap.length, length);
        EXPECT_FALSE(gap.atEdge);
        for (Eigen::Index f = gap.firstFrame - 1; f <= gap.firstFrame + length; ++f)
          ASSERT_TRUE(take.isValid(f, gap.marker));  // hidden and border samples are real data
        for (Eigen::Index f = gap.firstFrame; f < gap.firstFrame + length; ++f) {
          EXPECT_FALSE(hidden(f, gap.marker));
          hidden(f, gap.marker) = true;
        }
      }
      for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        const Eigen::Index missing =
            hidden.row(f).count() + (take.markerCount() - take.valid().row(f).count());
        ASSERT_LE(missing, take.markerCount() / 4) << f;
        shared = std::max<Eigen::Index>(shared, hidden.row(f).count());
      }
      if (gaps.size() > 1) {
        EXPECT_EQ(shared, static_cast<Eigen::Index>(gaps.size()));  // all overlap one frame
      }
    }
  }
}

TEST(FillEvaluation, HiddenGapsAvoidJumpsInTheTake)
{
  Take take = test::noseMoCapTake();
  for (Eigen::Index f = 480; f < take.frameCount(); ++f)  // marker 5 swaps with a marker 30 mm away
    take.setPosition(f, 5, take.position(f, 5) + Eigen::Vector3d(30, 0, 0));
  FillEvaluationOptions options;
  options.gapsPerCopy = 10;
  Eigen::Index overJump = 0;
  for (const bool skip : {true, false}) {
    options.skipJumps = skip;
    for (int copy = 0; copy < 200; ++copy)
      for (const Gap& gap : evaluationGaps(take, 60, copy, options))
        if (gap.marker == 5 && gap.firstFrame - 1 <= 480 && gap.firstFrame + gap.length + 1 >= 480) {
          EXPECT_FALSE(skip) << copy;
          ++overJump;
        }
  }
  EXPECT_GT(overJump, 0);  // without the rule such gaps do occur
}

TEST(FillEvaluation, IsSeededAndReproducible)
{
  FillEvaluationOptions options;
  options.copies = 2;
  options.gapLengths = {20};
  options.methods = {FillMethod::Linear, FillMethod::Zhang3};
  const FillEvaluation a = evaluateFill(test::noseMoCapTake(), options);
  const FillEvaluation b = evaluateFill(test::noseMoCapTake(), options);
  ASSERT_EQ(a.scores.size(), 2u);
  for (std::size_t i = 0; i < a.scores.size(); ++i) {
    EXPECT_EQ(a.scores[i].rmse, b.scores[i].rmse);
    EXPECT_EQ(a.scores[i].max, b.scores[i].max);
    EXPECT_GT(a.scores[i].gaps, 0);
    EXPECT_EQ(a.scores[i].samples, 20 * a.scores[i].gaps);
    EXPECT_LE(a.scores[i].meanError, a.scores[i].rmse);
    EXPECT_LE(a.scores[i].p95, a.scores[i].max);
  }
  options.seed = 2;
  EXPECT_NE(evaluateFill(test::noseMoCapTake(), options).scores[0].rmse, a.scores[0].rmse);
  // Millimetres whatever the take's units.
  Take metres = test::noseMoCapTake();
  metres.convertUnits(LengthUnit::Metre);
  options.seed = 1;
  EXPECT_NEAR(evaluateFill(metres, options).scores[0].rmse, a.scores[0].rmse, 1e-9 * a.scores[0].rmse);
}

TEST(FillEvaluation, BadOptionsAreRejected)
{
  FillEvaluationOptions options;
  options.copies = 0;
  EXPECT_THROW((void)evaluateFill(test::noseMoCapTake(), options), InvalidArgument);
  options = {};
  options.gapLengths = {};
  EXPECT_THROW((void)evaluateFill(test::noseMoCapTake(), options), InvalidArgument);
  options.gapLengths = {961};
  EXPECT_THROW((void)evaluateFill(test::noseMoCapTake(), options), InvalidArgument);
  options.gapLengths = {0};
  EXPECT_THROW((void)evaluateFill(test::noseMoCapTake(), options), InvalidArgument);
  options = {};
  options.methods = {};
  EXPECT_THROW((void)evaluateFill(test::noseMoCapTake(), options), InvalidArgument);
  options = {};
  options.neighbours = 0;
  EXPECT_THROW((void)evaluateFill(test::noseMoCapTake(), options), InvalidArgument);
  options = {};
  options.gapsPerCopy = -1;
  EXPECT_THROW((void)evaluateFill(test::noseMoCapTake(), options), InvalidArgument);
  EXPECT_THROW((void)evaluateFill(Take(), {}), InvalidArgument);
  EXPECT_THROW((void)evaluateFill(Take({"a", "b", "c"}, 100, 60.0), {}), InvalidArgument);
  EXPECT_THROW((void)evaluationGaps(test::noseMoCapTake(), 10, -1), InvalidArgument);
}

// The product targets on a real take (5 copies, lengths 10, 60 and 100 frames at 60 Hz):
// auto's RMSE at most 0.6 × zhang3's and at most every other method's at every length, and its
// mean error at most 1 mm on gaps up to one second.
TEST(FillEvaluation, AutoMeetsTheTargetsOnNoseMoCap)
{
#ifndef NDEBUG
  GTEST_SKIP() << "the accuracy targets run in optimised builds (about a second there, minutes in Debug "
                  "with sanitizers)";
#endif
  FillEvaluationOptions options;
  options.copies = 5;
  options.gapLengths = {10, 60, 100};
  const FillEvaluation evaluation = evaluateFill(test::noseMoCapTake(), options);
  std::map<std::pair<Eigen::Index, FillMethod>, FillScore> scores;
  for (const FillScore& score : evaluation.scores)
    scores[{score.gapLength, score.method}] = score;
  const double rate = test::noseMoCapTake().frameRate();
  for (const Eigen::Index length : options.gapLengths) {
    const FillScore& best = scores.at({length, FillMethod::Auto});
    EXPECT_EQ(best.unfilled, 0);
    EXPECT_LE(best.rmse, 0.6 * scores.at({length, FillMethod::Zhang3}).rmse) << length;
    for (const FillMethod method : allFillMethods())
      EXPECT_LE(best.rmse, scores.at({length, method}).rmse) << length << " " << fillMethodName(method);
    if (static_cast<double>(length) <= rate) {
      EXPECT_LE(best.meanError, 1.0) << length;
    }
    // Continuity: auto's velocity jump at the borders stays near the data's own.
    EXPECT_LE(best.borderVelocityJump, 4.0 * best.trueBorderVelocityJump) << length;
  }
}

} // namespace
} // namespace mocap
