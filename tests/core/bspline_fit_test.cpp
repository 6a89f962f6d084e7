#include "mocap/cleaning/bspline_fit.h"
#include "mocap/base/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mocap {
namespace {

// Three columns of polynomials of exactly `degree` with unrelated coefficients.
Eigen::MatrixXd polynomialSamples(Eigen::Index n, int degree)
{
  Eigen::MatrixXd samples(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(n - 1) * 2.0 - 1.0;
    for (Eigen::Index c = 0; c < 3; ++c) {
      double value = 0.0, power = 1.0;
      for (int k = 0; k <= degree; ++k) {
        value += (1.0 + 0.37 * static_cast<double>(k) - 0.9 * static_cast<double>(c)) * 20.0 * power;
        power *= t;
      }
      samples(i, c) = value;
    }
  }
  return samples;
}

TEST(BSplineFit, ReproducesPolynomialsUpToItsDegree)
{
  for (int degree = kMinBSplineDegree; degree <= kMaxBSplineDegree; ++degree)
    for (int p = 0; p <= degree; ++p)
      for (double spacing : {1.0, 2.5, 4.0, 9.0})
        for (Eigen::Index n : {Eigen::Index{degree + 2}, Eigen::Index{23}, Eigen::Index{200}}) {
          const Eigen::MatrixXd samples = polynomialSamples(n, p);
          const Eigen::MatrixXd fit = fitBSpline(samples, {degree, spacing});
          EXPECT_LT((fit - samples).cwiseAbs().maxCoeff(), 1e-9)
              << "degree " << degree << " polynomial " << p << " spacing " << spacing << " n " << n;
        }
}

TEST(BSplineFit, InterpolatesTheEndPointsAndSmoothsNoise)
{
  std::mt19937 random(5);
  std::normal_distribution<double> noise(0.0, 1.0);
  Eigen::MatrixXd samples(300, 3);
  for (Eigen::Index i = 0; i < 300; ++i)
    for (Eigen::Index c = 0; c < 3; ++c)
      samples(i, c) = 10.0 * std::sin(0.02 * static_cast<double>(i) + static_cast<double>(c)) + noise(random);
  for (int degree = kMinBSplineDegree; degree <= kMaxBSplineDegree; ++degree) {
    const Eigen::MatrixXd fit = fitBSpline(samples, {degree, 6.0});
    EXPECT_EQ(fit.row(0), samples.row(0));
    EXPECT_NEAR((fit.row(299) - samples.row(299)).norm(), 0.0, 1e-9);
    // The fit must be much closer to the clean curve than the noise (σ = 1) is.
    double squared = 0.0;
    for (Eigen::Index i = 0; i < 300; ++i)
      for (Eigen::Index c = 0; c < 3; ++c)
        squared +=
            std::pow(fit(i, c) - 10.0 * std::sin(0.02 * static_cast<double>(i) + static_cast<double>(c)), 2);
    EXPECT_LT(std::sqrt(squared / 900.0), 0.5) << "degree " << degree;
  }
}

TEST(BSplineFit, CoxDeBoorMatchesEquation12OnInteriorSpans)
{
  // Partition of unity and the known cubic values 1/6, 2/3, 1/6, 0 at t = 0.
  EXPECT_NEAR(uniformBSplineBasis(0, 3, 0.0), 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(uniformBSplineBasis(1, 3, 0.0), 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(uniformBSplineBasis(2, 3, 0.0), 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(uniformBSplineBasis(3, 3, 0.0), 0.0, 1e-15);
  for (int n = 2; n <= 7; ++n)
    for (double t : {0.0, 0.3, 0.75}) {
      double sum = 0.0;
      for (int k = 0; k <= n; ++k)
        sum += uniformBSplineBasis(k, n, t);
      EXPECT_NEAR(sum, 1.0, 1e-12);
    }
  // The fitter evaluates its curve by Cox–de Boor; on interior spans (uniform knots) that must be
  // eq 11 with eq 12's weights: curve(i) = Σ_k F_{k,n}(t) P_{j+k}, span j = ⌊i / h⌋, t = i / h − j.
  const Eigen::Index count = 101;
  for (int degree = kMinBSplineDegree; degree <= kMaxBSplineDegree; ++degree) {
    const BSplineFitter fitter(count, {degree, 4.0});
    ASSERT_EQ(fitter.spanCount(), 25);
    const Eigen::MatrixXd samples = Eigen::MatrixXd::Random(count, 1);
    const Eigen::MatrixXd controls = fitter.controlPoints(samples);
    const Eigen::MatrixXd curve = fitter.fit(samples);
    for (Eigen::Index i = 4 * degree; i < count - 4 * degree; ++i) {
      const Eigen::Index span = i / 4;
      const double t = static_cast<double>(i - 4 * span) / 4.0;
      double expected = 0.0;
      for (int k = 0; k <= degree; ++k)
        expected += uniformBSplineBasis(k, degree, t) * controls(span + k, 0);
      EXPECT_NEAR(curve(i, 0), expected, 1e-12) << "degree " << degree << " frame " << i;
    }
  }
}

TEST(BSplineFit, ShortRunsComeBackUnchangedAndBadInputThrows)
{
  const Eigen::MatrixXd samples = Eigen::MatrixXd::Random(4, 3);
  EXPECT_EQ(fitBSpline(samples, {3, 4.0}), samples);  // 4 < degree + 2
  EXPECT_EQ(fitBSpline(Eigen::MatrixXd(0, 3), {3, 4.0}).rows(), 0);
  EXPECT_THROW((void)fitBSpline(samples, {12, 4.0}), InvalidArgument);
  EXPECT_THROW((void)fitBSpline(samples, {1, 4.0}), InvalidArgument);
  EXPECT_THROW((void)fitBSpline(samples, {3, 0.5}), InvalidArgument);
  EXPECT_THROW((void)fitBSpline(samples, {3, std::nan("")}), InvalidArgument);
  Eigen::MatrixXd bad = Eigen::MatrixXd::Random(20, 3);
  bad(7, 1) = std::nan("");
  EXPECT_THROW((void)fitBSpline(bad, {3, 4.0}), InvalidArgument);
  EXPECT_THROW(BSplineFitter(4, {3, 4.0}), InvalidArgument);
  const BSplineFitter fitter(20, {3, 4.0});
  EXPECT_THROW((void)fitter.fit(Eigen::MatrixXd::Zero(19, 3)), InvalidArgument);
}

TEST(BSplineFit, EveryRunLengthAndSpacingGivesAWellPosedFit)
{
  for (int degree = kMinBSplineDegree; degree <= kMaxBSplineDegree; ++degree)
    for (Eigen::Index n = minBSplineRunLength(degree); n < 60; ++n)
      for (double spacing : {1.0, 1.3, 2.0, 3.7, 50.0}) {
        const BSplineFitter fitter(n, {degree, spacing});
        EXPECT_LT(fitter.controlPointCount(), n);
        EXPECT_GE(fitter.spanCount(), 1);
      }
}

} // namespace
} // namespace mocap
