#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/evaluation/smoothing_evaluation.h"
#include "mocap/io/take_io.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mocap {
namespace {

TEST(SmoothingEvaluation, NoiseIsSeededAndHasTheRequestedSize)
{
  const Take take = readTake(test::dataFile("trc/NoseMoCap.trc"));
  const Take a = addMeasurementNoise(take, 1.0, 7);
  const Take b = addMeasurementNoise(take, 1.0, 7);
  const Take c = addMeasurementNoise(take, 1.0, 8);
  EXPECT_EQ(a.trajectory(3), b.trajectory(3));
  EXPECT_NE(a.trajectory(3), c.trajectory(3));
  double squared = 0.0;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    squared += (a.trajectory(m) - take.trajectory(m)).squaredNorm();
  const double rms = std::sqrt(squared / static_cast<double>(3 * take.markerCount() * take.frameCount()));
  EXPECT_NEAR(rms, 1.0, 0.02);
  EXPECT_THROW((void)addMeasurementNoise(take, -1.0, 1), InvalidArgument);
  EXPECT_THROW((void)addMeasurementNoise(take, std::nan(""), 1), InvalidArgument);
}

// The default must be no worse than GCVSPL (cubic, GCV) on either measure: on the sample take
// (100 Hz, gaps, two label swaps that every smoother blurs) and on NoseMoCap (60 Hz, no gaps).
TEST(SmoothingEvaluation, DefaultIsNoWorseThanGcvspl)
{
  SmoothOptions gcv;
  gcv.method = SmoothMethod::Gcvspl;
  gcv.gcvsplMode = SmoothingSplineMode::Gcv;
  gcv.gcvsplDegree = 3;
  for (const auto& file : {test::sampleTake(), test::dataFile("trc/NoseMoCap.trc")}) {
    const Take take = readTake(file);
    for (double noise : {0.5, 1.0}) {
      SmoothingEvaluationOptions options;
      options.noiseMm = noise;
      options.methods = {SmoothOptions{}, gcv};
      const SmoothingEvaluation result = evaluateSmoothing(take, options);
      ASSERT_EQ(result.scores.size(), 2u);
      EXPECT_TRUE(result.scores[0].isDefault);
      EXPECT_LE(result.scores[0].rmse, result.scores[1].rmse * (1.0 + 1e-12)) << file;
      EXPECT_LE(result.scores[0].accelerationRmse, result.scores[1].accelerationRmse * (1.0 + 1e-12)) << file;
      EXPECT_NEAR(result.noisyRmse, noise, 0.05 * noise);
      EXPECT_LT(result.scores[0].rmse, 0.6 * result.noisyRmse) << file;
    }
  }
}

TEST(SmoothingEvaluation, SmoothingRecoversTheAccelerationOfASmoothTake)
{
  const Take take = readTake(test::dataFile("trc/NoseMoCap.trc"));
  SmoothingEvaluationOptions options;
  options.noiseMm = 1.0;
  const SmoothingEvaluation result = evaluateSmoothing(take, options);
  ASSERT_EQ(result.scores.size(), evaluatedSmoothOptions().size());
  EXPECT_EQ(result.samples, take.markerCount() * take.frameCount());
  EXPECT_EQ(result.accelerationSamples, take.markerCount() * (take.frameCount() - 2));
  for (const SmoothingScore& score : result.scores) {
    EXPECT_LT(score.rmse, result.noisyRmse) << score.parameters;
    EXPECT_LT(score.accelerationRmse, 0.2 * result.noisyAccelerationRmse) << score.parameters;
  }
  EXPECT_LT(result.scores[0].accelerationRmse, 0.05 * result.noisyAccelerationRmse);
}

TEST(SmoothingEvaluation, SmoothnessTableFollowsThePaperAndRunsThePreprocessing)
{
  const Take take = readTake(test::sampleTake());
  SmoothnessTableOptions options;
  bool preprocessed = false;
  options.preprocess = [&preprocessed](Take&) { preprocessed = true; };
  const SmoothnessTable table = smoothnessTable(take, options);
  ASSERT_EQ(table.rows.size(), 6u);
  EXPECT_TRUE(preprocessed);
  EXPECT_EQ(table.rows[0].order, 3);
  EXPECT_EQ(table.rows[4].order, 7);
  EXPECT_EQ(table.rows[5].preprocessing, "spikes");
  EXPECT_EQ(static_cast<Eigen::Index>(table.markers.size()), take.markerCount());
  for (const SmoothnessRow& row : table.rows) {
    EXPECT_GT(row.smoothness, 0.0);
    EXPECT_LT(row.smoothness, table.rawSmoothness);  // any of the fits is smoother than the capture
  }
  // A do-nothing preprocessing leaves the order-3 figure as it was.
  EXPECT_DOUBLE_EQ(table.rows[5].smoothness, table.rows[0].smoothness);
  options.markers = {take.markerCount()};
  EXPECT_THROW((void)smoothnessTable(take, options), InvalidArgument);
}

TEST(SmoothingEvaluation, DisplacementLengthVarianceIsThePopulationVariance)
{
  Eigen::Matrix<double, Eigen::Dynamic, 3> xyz = Eigen::Matrix<double, Eigen::Dynamic, 3>::Zero(6, 3);
  // Steps of length 1, 3, (gap), 2: variance of {1, 3, 2} (the step into the gap is not counted).
  xyz(1, 0) = 1.0;
  xyz(2, 0) = 4.0;
  xyz(3, 0) = 1000.0;
  xyz(4, 1) = 0.0;
  xyz(5, 1) = 2.0;
  ValidMask valid = ValidMask::Constant(6, true);
  valid(3) = false;
  EXPECT_DOUBLE_EQ(displacementLengthVariance(xyz, valid), 2.0 / 3.0);
  EXPECT_EQ(displacementLengthVariance(xyz.topRows(1), valid.head(1)), 0.0);
  EXPECT_THROW((void)displacementLengthVariance(xyz, valid.head(5)), InvalidArgument);
}

} // namespace
} // namespace mocap
