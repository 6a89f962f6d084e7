#include "mocap/math/banded_cholesky.h"
#include "mocap/base/error.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <random>

namespace mocap {
namespace {

// A random symmetric positive definite matrix of half-bandwidth b, as band and dense.
std::pair<BandedCholesky::Band, Eigen::MatrixXd> randomBandMatrix(Eigen::Index n, Eigen::Index b,
                                                                  unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = std::max<Eigen::Index>(0, i - b); j < i; ++j)
      dense(i, j) = dense(j, i) = uniform(random);
  for (Eigen::Index i = 0; i < n; ++i)
    dense(i, i) = 2.0 * static_cast<double>(b) + 1.0 + uniform(random);
  BandedCholesky::Band band = BandedCholesky::Band::Zero(n, b + 1);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index k = 0; k <= std::min(b, i); ++k)
      band(i, k) = dense(i, i - k);
  return {band, dense};
}

TEST(BandedCholesky, SolvesLikeADenseFactorisation)
{
  for (Eigen::Index b : {0, 1, 3, 7}) {
    const auto [band, dense] = randomBandMatrix(40, b, 3u + static_cast<unsigned>(b));
    const BandedCholesky factor(band);
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(40, 3);
    const Eigen::MatrixXd expected = dense.ldlt().solve(rhs);
    factor.solveInPlace(rhs);
    EXPECT_LT((rhs - expected).cwiseAbs().maxCoeff(), 1e-12) << "bandwidth " << b;
  }
}

TEST(BandedCholesky, InverseBandMatchesTheDenseInverse)
{
  for (Eigen::Index b : {1, 2, 3}) {
    const auto [band, dense] = randomBandMatrix(30, b, 11u);
    const BandedCholesky::Band inverse = BandedCholesky(band).inverseBand();
    const Eigen::MatrixXd expected = dense.inverse();
    for (Eigen::Index i = 0; i < 30; ++i)
      for (Eigen::Index k = 0; k <= std::min(b, i); ++k)
        EXPECT_NEAR(inverse(i, k), expected(i, i - k), 1e-12);
  }
}

TEST(BandedCholesky, RejectsIndefiniteMatricesAndWrongSizes)
{
  BandedCholesky::Band band(2, 2);
  band << 1.0, 0.0, 1.0, 2.0;  // [[1, 2], [2, 1]]
  EXPECT_THROW(BandedCholesky{band}, InvalidArgument);
  band << 1.0, 0.0, std::nan(""), 0.0;
  EXPECT_THROW(BandedCholesky{band}, InvalidArgument);
  const BandedCholesky ok(BandedCholesky::Band::Ones(3, 1));
  Eigen::MatrixXd wrong(2, 1);
  EXPECT_THROW(ok.solveInPlace(wrong), InvalidArgument);
}

} // namespace
} // namespace mocap
