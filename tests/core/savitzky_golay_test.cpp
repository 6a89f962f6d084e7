#include "mocap/base/error.h"
#include "mocap/cleaning/savitzky_golay.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mocap {
namespace {

TEST(SavitzkyGolay, ReproducesPolynomialsUpToItsDegreeIncludingTheEnds)
{
  for (int window : {3, 5, 9, 21})
    for (int degree = 0; degree < std::min(window, 6); ++degree) {
      Eigen::MatrixXd samples(80, 2);
      for (Eigen::Index i = 0; i < 80; ++i) {
        const double t = static_cast<double>(i) / 10.0 - 4.0;
        samples(i, 0) = std::pow(t, degree) + 2.0;
        samples(i, 1) = -3.0 * std::pow(t, degree) + t;
      }
      if (degree == 0)
        samples.col(1).setConstant(7.0);
      const Eigen::MatrixXd out = savitzkyGolay(samples, {window, degree});
      EXPECT_LT((out - samples).cwiseAbs().maxCoeff(), 1e-9) << "window " << window << " degree " << degree;
    }
}

TEST(SavitzkyGolay, CentreWeightsAreTheClassicTable)
{
  // Savitzky & Golay's quadratic/cubic 5-point smoothing weights: (−3, 12, 17, 12, −3) / 35.
  const Eigen::MatrixXd weights = savitzkyGolayWeights({5, 2});
  const Eigen::RowVectorXd expected = (Eigen::RowVectorXd(5) << -3, 12, 17, 12, -3).finished() / 35.0;
  EXPECT_LT((weights.row(2) - expected).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((savitzkyGolayWeights({5, 3}).row(2) - expected).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(SavitzkyGolay, BadOptionsThrowAndShortRunsComeBackUnchanged)
{
  const Eigen::MatrixXd samples = Eigen::MatrixXd::Random(30, 3);
  EXPECT_THROW((void)savitzkyGolay(samples, {4, 2}), InvalidArgument);
  EXPECT_THROW((void)savitzkyGolay(samples, {1, 0}), InvalidArgument);
  EXPECT_THROW((void)savitzkyGolay(samples, {5, 5}), InvalidArgument);
  EXPECT_THROW((void)savitzkyGolay(samples, {31, 12}), InvalidArgument);
  EXPECT_THROW((void)savitzkyGolay(samples, {5, -1}), InvalidArgument);
  EXPECT_THROW((void)savitzkyGolay(samples, {100001, 3}), InvalidArgument);
  Eigen::MatrixXd bad = samples;
  bad(0, 0) = std::nan("");
  EXPECT_THROW((void)savitzkyGolay(bad, {5, 2}), InvalidArgument);
  const Eigen::MatrixXd shortRun = Eigen::MatrixXd::Random(8, 3);
  EXPECT_EQ(savitzkyGolay(shortRun, {9, 3}), shortRun);
}

} // namespace
} // namespace mocap
