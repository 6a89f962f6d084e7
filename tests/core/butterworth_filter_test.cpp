#include "mocap/cleaning/butterworth_filter.h"
#include "mocap/base/error.h"
#include "mocap/cleaning/winter_cutoff.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mocap {
namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::MatrixXd sine(Eigen::Index n, double frequencyHz, double frameRate, double amplitude,
                     double phase = 0.3)
{
  Eigen::MatrixXd samples(n, 1);
  for (Eigen::Index i = 0; i < n; ++i)
    samples(i, 0) =
        amplitude * std::sin(2.0 * kPi * frequencyHz * static_cast<double>(i) / frameRate + phase);
  return samples;
}

TEST(ButterworthFilter, PassesConstantsLinesAndSlowSinesUnchanged)
{
  Eigen::MatrixXd constant = Eigen::MatrixXd::Constant(500, 3, 1234.5);
  EXPECT_LT((butterworthFilter(constant, 60.0, 6.0) - constant).cwiseAbs().maxCoeff(), 1e-6);
  Eigen::MatrixXd line(500, 1);
  for (Eigen::Index i = 0; i < 500; ++i)
    line(i, 0) = 3.0 + 0.25 * static_cast<double>(i);
  EXPECT_LT((butterworthFilter(line, 60.0, 6.0) - line).cwiseAbs().maxCoeff(), 1e-6);
  // A 0.1 Hz, 1 mm sine at 60 Hz, ends included (they start and stop at arbitrary phases).
  const Eigen::MatrixXd slow = sine(700, 0.1, 60.0, 1.0);
  EXPECT_LT((butterworthFilter(slow, 60.0, 6.0) - slow).cwiseAbs().maxCoeff(), 1e-6);
  // Faster and larger, 0.2 Hz and 10 mm: the middle follows the design gain, the ends stay within 1e-5
  // relative.
  const Eigen::MatrixXd faster = sine(700, 0.2, 60.0, 10.0);
  const Eigen::MatrixXd error = butterworthFilter(faster, 60.0, 6.0) - faster;
  EXPECT_LT(error.middleRows(100, 500).cwiseAbs().maxCoeff(),
            10.0 * (1.0 - butterworthGain(0.2, 60.0, 6.0)) + 1e-9);
  EXPECT_LT(error.cwiseAbs().maxCoeff(), 1e-4);
}

TEST(ButterworthFilter, AttenuatesATonePastTheCutoffAsDesigned)
{
  const double rate = 100.0, cutoff = 6.0;
  EXPECT_NEAR(butterworthGain(cutoff, rate, cutoff), 1.0 / std::sqrt(2.0), 1e-12);
  for (double tone : {6.0, 12.0, 20.0}) {
    const Eigen::MatrixXd input = sine(4000, tone, rate, 1.0);
    const Eigen::MatrixXd output = butterworthFilter(input, rate, cutoff);
    // Amplitude in the middle, far from the ends: project on sin and cos of the tone.
    double s = 0.0, c = 0.0, ss = 0.0, cc = 0.0;
    for (Eigen::Index i = 1000; i < 3000; ++i) {
      const double phase = 2.0 * kPi * tone * static_cast<double>(i) / rate + 0.3;
      s += output(i, 0) * std::sin(phase);
      c += output(i, 0) * std::cos(phase);
      ss += std::sin(phase) * std::sin(phase);
      cc += std::cos(phase) * std::cos(phase);
    }
    const double gain = s / ss;
    EXPECT_NEAR(gain, butterworthGain(tone, rate, cutoff), 1e-6) << tone << " Hz";
    EXPECT_NEAR(c / cc, 0.0, 1e-6) << "zero lag at " << tone << " Hz";
  }
  // The two passes together fall off like a 4th-order filter, −24 dB per octave past the cutoff.
  EXPECT_NEAR(butterworthGain(24.0, rate, cutoff) / butterworthGain(12.0, rate, cutoff), 1.0 / 16.0, 0.03);
}

TEST(ButterworthFilter, EndsDoNotRingOnNoise)
{
  std::mt19937 random(9);
  std::normal_distribution<double> noise(0.0, 1.0);
  Eigen::MatrixXd samples(600, 1);
  for (Eigen::Index i = 0; i < 600; ++i)
    samples(i, 0) = 50.0 + noise(random);
  const Eigen::MatrixXd output = butterworthFilter(samples, 60.0, 6.0);
  // The filtered noise at the ends stays as small as in the middle.
  EXPECT_LT((output.topRows(20).array() - 50.0).abs().maxCoeff(), 1.5);
  EXPECT_LT((output.bottomRows(20).array() - 50.0).abs().maxCoeff(), 1.5);
}

TEST(ButterworthFilter, BadInputThrowsAndShortRunsComeBackUnchanged)
{
  const Eigen::MatrixXd samples = Eigen::MatrixXd::Random(50, 3);
  EXPECT_THROW((void)butterworthFilter(samples, 60.0, 30.0), InvalidArgument);
  EXPECT_THROW((void)butterworthFilter(samples, 60.0, 0.0), InvalidArgument);
  EXPECT_THROW((void)butterworthFilter(samples, 0.0, 6.0), InvalidArgument);
  EXPECT_THROW((void)butterworthFilter(samples, std::nan(""), 6.0), InvalidArgument);
  Eigen::MatrixXd bad = samples;
  bad(3, 2) = std::numeric_limits<double>::infinity();
  EXPECT_THROW((void)butterworthFilter(bad, 60.0, 6.0), InvalidArgument);
  const Eigen::MatrixXd three = Eigen::MatrixXd::Random(3, 3);
  EXPECT_EQ(butterworthFilter(three, 60.0, 6.0), three);
  EXPECT_EQ(butterworthFilter(Eigen::MatrixXd(0, 3), 60.0, 6.0).rows(), 0);
}

TEST(WinterCutoff, FindsACutoffBetweenSignalAndNoise)
{
  // 1 Hz motion plus 0.5 mm white noise at 100 Hz: the residual analysis must land above the
  // motion and well below the noise band's top.
  std::mt19937 random(4);
  std::normal_distribution<double> noise(0.0, 0.5);
  Eigen::Matrix<double, Eigen::Dynamic, 3> xyz(2000, 3);
  for (Eigen::Index i = 0; i < 2000; ++i)
    for (Eigen::Index c = 0; c < 3; ++c)
      xyz(i, c) = 20.0 * std::sin(2.0 * kPi * 1.0 * static_cast<double>(i) / 100.0 + static_cast<double>(c)) +
                  noise(random);
  const ValidMask valid = ValidMask::Constant(2000, true);
  const WinterCutoff winter = winterCutoff(xyz, valid, 100.0);
  EXPECT_GT(winter.cutoffHz, 1.5);
  EXPECT_LT(winter.cutoffHz, 15.0);
  EXPECT_NEAR(winter.noiseRms, 0.5, 0.1);
  EXPECT_EQ(winter.frequenciesHz.size(), winter.residualRms.size());
  EXPECT_THROW((void)winterCutoff(xyz, ValidMask::Constant(3, true), 100.0), InvalidArgument);
  const WinterCutoff none = winterCutoff(xyz, ValidMask::Constant(2000, false), 100.0);
  EXPECT_DOUBLE_EQ(none.cutoffHz, 40.0);
}

} // namespace
} // namespace mocap
