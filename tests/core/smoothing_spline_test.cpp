#include "mocap/base/error.h"
#include "mocap/cleaning/smoothing_spline.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mocap {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Dense reference: K = Dᵀ R⁻¹ D with D the m-th difference matrix and R the B-spline Gram matrix,
// g = (I + λK)⁻¹ y. Independent of the banded Reinsch solve and the Hutchinson–de Hoog trace.
Eigen::MatrixXd densePenalty(Eigen::Index n, int m)
{
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n - m, n);
  const std::vector<double> coefficients =
      m == 2 ? std::vector<double>{1, -2, 1} : std::vector<double>{-1, 3, -3, 1};
  const std::vector<double> gram =
      m == 2 ? std::vector<double>{2.0 / 3, 1.0 / 6} : std::vector<double>{11.0 / 20, 13.0 / 60, 1.0 / 120};
  for (Eigen::Index i = 0; i < n - m; ++i)
    for (int r = 0; r <= m; ++r)
      d(i, i + r) = coefficients[static_cast<std::size_t>(r)];
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(n - m, n - m);
  for (Eigen::Index i = 0; i < n - m; ++i)
    for (Eigen::Index j = 0; j < n - m; ++j)
      if (std::abs(i - j) < static_cast<Eigen::Index>(gram.size()))
        r(i, j) = gram[static_cast<std::size_t>(std::abs(i - j))];
  return d.transpose() * r.ldlt().solve(d);
}

Eigen::MatrixXd noisySine(Eigen::Index n, double rate, double sigma, unsigned seed, Eigen::MatrixXd* clean)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  Eigen::MatrixXd truth(n, 3);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index c = 0; c < 3; ++c)
      truth(i, c) =
          15.0 * std::sin(2.0 * kPi * (0.7 + 0.3 * static_cast<double>(c)) * static_cast<double>(i) / rate) +
          0.001 * static_cast<double>(i * i) / rate;
  Eigen::MatrixXd noisy = truth;
  for (Eigen::Index i = 0; i < noisy.size(); ++i)
    noisy(i) += noise(random);
  *clean = truth;
  return noisy;
}

double rms(const Eigen::MatrixXd& a)
{
  return std::sqrt(a.squaredNorm() / static_cast<double>(a.size()));
}

TEST(SmoothingSpline, MatchesTheDenseSolutionAndTrace)
{
  for (int degree : {3, 5}) {
    const int m = (degree + 1) / 2;
    const Eigen::Index n = 40;
    const Eigen::MatrixXd y = Eigen::MatrixXd::Random(n, 3);
    const double lambda = smoothingSplineLambda(degree, 100.0, 8.0);
    const SmoothingSplineFit fit = smoothingSpline(y, 100.0, {degree, SmoothingSplineMode::Cutoff, 0.0, 8.0});
    const Eigen::MatrixXd influence =
        (Eigen::MatrixXd::Identity(n, n) + lambda * densePenalty(n, m)).inverse();
    EXPECT_LT((fit.smoothed - influence * y).cwiseAbs().maxCoeff(), 1e-10) << degree;
    EXPECT_NEAR(fit.degreesOfFreedom, influence.trace(), 1e-9) << degree;
    EXPECT_DOUBLE_EQ(fit.lambda, lambda);
    EXPECT_NEAR(fit.equivalentCutoffHz, 8.0, 1e-9);
  }
}

TEST(SmoothingSpline, ReproducesPolynomialsBelowThePenaltyOrder)
{
  Eigen::MatrixXd y(300, 3);
  for (Eigen::Index i = 0; i < 300; ++i) {
    const double t = static_cast<double>(i);
    y.row(i) << 3.0 + 0.5 * t, -2.0 * t, 1e-3 * t * t + t;
  }
  // Cubic: lines pass whatever λ (checked with a very low cutoff).
  const Eigen::MatrixXd lines = y.leftCols(2);
  EXPECT_LT((smoothingSpline(lines, 100.0, {3, SmoothingSplineMode::Cutoff, 0.0, 0.5}).smoothed - lines)
                .cwiseAbs()
                .maxCoeff(),
            1e-6);
  // Quintic: quadratics pass.
  EXPECT_LT((smoothingSpline(y, 100.0, {5, SmoothingSplineMode::Cutoff, 0.0, 1.0}).smoothed - y)
                .cwiseAbs()
                .maxCoeff(),
            1e-6);
}

TEST(SmoothingSpline, GcvAndKnownVarianceReduceTheErrorOfNoisyData)
{
  for (int degree : {3, 5})
    for (double sigma : {0.5, 2.0}) {
      Eigen::MatrixXd clean;
      const Eigen::MatrixXd noisy = noisySine(1500, 100.0, sigma, 17u, &clean);
      const double raw = rms(noisy - clean);
      const SmoothingSplineFit gcv =
          smoothingSpline(noisy, 100.0, {degree, SmoothingSplineMode::Gcv, 0.0, 6.0});
      EXPECT_LT(rms(gcv.smoothed - clean), 0.35 * raw) << "degree " << degree << " sigma " << sigma;
      EXPECT_GT(gcv.equivalentCutoffHz, 0.5);
      EXPECT_LT(gcv.equivalentCutoffHz, 20.0);
      const SmoothingSplineFit known =
          smoothingSpline(noisy, 100.0, {degree, SmoothingSplineMode::ErrorVariance, sigma * sigma, 6.0});
      EXPECT_LT(rms(known.smoothed - clean), 0.35 * raw) << "degree " << degree << " sigma " << sigma;
    }
}

TEST(SmoothingSpline, CutoffModeIsMinus3dBAtTheCutoff)
{
  const double rate = 100.0;
  Eigen::MatrixXd tone(4000, 1);
  for (Eigen::Index i = 0; i < 4000; ++i)
    tone(i, 0) = std::sin(2.0 * kPi * 5.0 * static_cast<double>(i) / rate);
  for (int degree : {3, 5}) {
    const Eigen::MatrixXd out =
        smoothingSpline(tone, rate, {degree, SmoothingSplineMode::Cutoff, 0.0, 5.0}).smoothed;
    const double gain = out.middleRows(1000, 2000).cwiseAbs().maxCoeff();
    EXPECT_NEAR(gain, 1.0 / std::sqrt(2.0), 2e-3) << degree;
  }
  EXPECT_NEAR(smoothingSplineCutoffHz(3, rate, smoothingSplineLambda(3, rate, 7.5)), 7.5, 1e-9);
}

TEST(SmoothingSpline, BadInputThrowsAndShortRunsComeBackUnchanged)
{
  const Eigen::MatrixXd y = Eigen::MatrixXd::Random(20, 3);
  EXPECT_THROW((void)smoothingSpline(y, 100.0, {4, SmoothingSplineMode::Gcv, 0.0, 6.0}), InvalidArgument);
  EXPECT_THROW((void)smoothingSpline(y, 100.0, {3, SmoothingSplineMode::ErrorVariance, -1.0, 6.0}),
               InvalidArgument);
  EXPECT_THROW((void)smoothingSpline(y, 100.0, {3, SmoothingSplineMode::Cutoff, 0.0, 50.0}), InvalidArgument);
  EXPECT_THROW((void)smoothingSpline(y, 0.0, {}), InvalidArgument);
  Eigen::MatrixXd bad = y;
  bad(5, 1) = std::nan("");
  EXPECT_THROW((void)smoothingSpline(bad, 100.0, {}), InvalidArgument);
  const Eigen::MatrixXd five = Eigen::MatrixXd::Random(5, 3);
  EXPECT_EQ(smoothingSpline(five, 100.0, {5, SmoothingSplineMode::Gcv, 0.0, 6.0}).smoothed, five);
  EXPECT_EQ(smoothingSpline(five.topRows(3), 100.0, {}).smoothed, five.topRows(3));
  EXPECT_EQ(smoothingSpline(Eigen::MatrixXd(0, 3), 100.0, {}).smoothed.rows(), 0);
  EXPECT_EQ(parseSmoothingSplineMode("variance"), SmoothingSplineMode::ErrorVariance);
  EXPECT_FALSE(parseSmoothingSplineMode("GCV"));
}

} // namespace
} // namespace mocap
