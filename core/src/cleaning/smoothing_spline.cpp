#include "mocap/cleaning/smoothing_spline.h"

#include "mocap/base/enum_table.h"
#include "mocap/math/banded_cholesky.h"
#include "mocap/base/error.h"
#include "mocap/math/pi.h"

#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace mocap {

namespace {

// Search range of the equivalent cutoff, as fractions of the frame rate.
constexpr double kLowestCutoff = 0.005;
constexpr double kHighestCutoff = 0.45;
// A 13-point scan steps λ by a factor of about 4.6 (the equivalent cutoff by about 1.3–1.5);
// 12 golden-section steps then narrow the two-step bracket to 1 % in log λ.
constexpr int kScanPoints = 13;
constexpr int kGoldenSteps = 12;

int penaltyOrder(int degree)
{
  return (degree + 1) / 2;
}

// Gram matrix R of the order-m B-splines on a unit grid: Toeplitz with R(i, i ± k) = M_{2m}(m + k),
// the cardinal B-spline of order 2m at the integers.
std::array<double, 3> gram(int m)
{
  if (m == 2)
    return {2.0 / 3.0, 1.0 / 6.0, 0.0};
  return {11.0 / 20.0, 13.0 / 60.0, 1.0 / 120.0};
}

// QᵀQ = Δ^m (Δ^m)ᵀ: Toeplitz with (−1)^k C(2m, m + k).
std::array<double, 4> differenceGram(int m)
{
  if (m == 2)
    return {6.0, -4.0, 1.0, 0.0};
  return {20.0, -15.0, 6.0, -1.0};
}

// Coefficients of the m-th forward difference: (Δ^m y)_i = Σ_r d_r y_{i+r}.
std::array<double, 4> difference(int m)
{
  if (m == 2)
    return {1.0, -2.0, 1.0, 0.0};
  return {-1.0, 3.0, -3.0, 1.0};
}

// λ (frame units) at which the equivalent filter has gain 1/√2 at ω (radians per sample).
double lambdaAt(int m, double omega)
{
  const auto r = gram(m);
  const double symbol = r[0] + 2.0 * r[1] * std::cos(omega) + 2.0 * r[2] * std::cos(2.0 * omega);
  const double difference2 = std::pow(2.0 * std::sin(0.5 * omega), 2 * m);
  return (std::sqrt(2.0) - 1.0) * symbol / difference2;
}

void checkRate(double frameRate)
{
  if (!std::isfinite(frameRate) || frameRate <= 0.0)
    throw InvalidArgument("smoothing spline: frame rate must be finite and positive, not " +
                          std::to_string(frameRate));
}

// The Reinsch system of one run, evaluated for any λ.
class ReinschSystem
{
public:
  ReinschSystem(const Eigen::Ref<const Eigen::MatrixXd>& y, int m) : m_y(y), m_m(m)
  {
    const Eigen::Index n = y.rows();
    const auto d = difference(m);
    m_qty = Eigen::MatrixXd::Zero(n - m, y.cols());
    for (Eigen::Index i = 0; i < n - m; ++i)
      for (int r = 0; r <= m; ++r)
        m_qty.row(i) += d[static_cast<std::size_t>(r)] * y.row(i + r);
  }

  struct Evaluation
  {
    double rss = 0.0;    // per coordinate: Σ residual² / columns
    double trace = 0.0;  // tr(I − A)
  };

  // Solves for λ; with `smoothed` also writes g = y − λ Q γ.
  Evaluation evaluate(double lambda, Eigen::MatrixXd* smoothed) const
  {
    const Eigen::Index n = m_y.rows();
    const Eigen::Index size = n - m_m;
    const auto r = gram(m_m);
    const auto c = differenceGram(m_m);
    const auto d = difference(m_m);
    BandedCholesky::Band band(size, m_m + 1);
    for (int k = 0; k <= m_m; ++k) {
      const auto uk = static_cast<std::size_t>(k);
      band.col(k).setConstant((k < 3 ? r[uk] : 0.0) + lambda * c[uk]);
    }
    const BandedCholesky factor(std::move(band));
    m_gamma = m_qty;
    factor.solveInPlace(m_gamma);
    // Residual y − g = λ Q γ, column by column.
    m_residual.setZero(n, m_y.cols());
    for (Eigen::Index col = 0; col < m_y.cols(); ++col) {
      const double* gamma = m_gamma.col(col).data();
      double* residual = m_residual.col(col).data();
      for (int k = 0; k <= m_m; ++k) {
        const double weight = lambda * d[static_cast<std::size_t>(k)];
        for (Eigen::Index i = 0; i < size; ++i)
          residual[i + k] += weight * gamma[i];
      }
    }
    Evaluation e;
    e.rss = m_residual.squaredNorm() / static_cast<double>(m_y.cols());
    const BandedCholesky::Band inverse = factor.inverseBand();
    double trace = c[0] * inverse.col(0).sum();
    for (Eigen::Index k = 1; k <= m_m; ++k)
      trace += 2.0 * c[static_cast<std::size_t>(k)] * inverse.col(k).tail(size - k).sum();
    e.trace = lambda * trace;
    if (smoothed)
      *smoothed = m_y - m_residual;
    return e;
  }

private:
  Eigen::Ref<const Eigen::MatrixXd> m_y;
  int m_m;
  Eigen::MatrixXd m_qty;
  // Work space reused across evaluations.
  mutable Eigen::MatrixXd m_gamma;
  mutable Eigen::MatrixXd m_residual;
};

} // namespace

namespace {

constexpr EnumTable<SmoothingSplineMode, 3> kModes{{{
    {SmoothingSplineMode::Gcv, "gcv"},
    {SmoothingSplineMode::ErrorVariance, "variance"},
    {SmoothingSplineMode::Cutoff, "cutoff"},
}}};

} // namespace

std::optional<SmoothingSplineMode> parseSmoothingSplineMode(std::string_view name)
{
  return kModes.parse(name);
}

std::string_view smoothingSplineModeName(SmoothingSplineMode mode)
{
  return kModes.name(mode, "gcv");
}

void checkSmoothingSplineOptions(const SmoothingSplineOptions& options)
{
  if (options.degree != 3 && options.degree != 5)
    throw InvalidArgument("smoothing spline degree must be 3 (cubic) or 5 (quintic), not " +
                          std::to_string(options.degree));
  if (!std::isfinite(options.errorVariance) || options.errorVariance < 0.0)
    throw InvalidArgument("smoothing spline error variance must be finite and ≥ 0, not " +
                          std::to_string(options.errorVariance));
  if (!std::isfinite(options.cutoffHz) || options.cutoffHz <= 0.0)
    throw InvalidArgument("smoothing spline cutoff must be finite and positive, not " +
                          std::to_string(options.cutoffHz));
}

Eigen::Index minSmoothingSplineRunLength(int degree)
{
  return 2 * penaltyOrder(degree);
}

double smoothingSplineLambda(int degree, double frameRate, double cutoffHz)
{
  checkSmoothingSplineOptions({degree, SmoothingSplineMode::Cutoff, 0.0, cutoffHz});
  checkRate(frameRate);
  if (cutoffHz >= 0.5 * frameRate)
    throw InvalidArgument("smoothing spline cutoff must be below the Nyquist frequency (" +
                          std::to_string(0.5 * frameRate) + " Hz), not " + std::to_string(cutoffHz) + " Hz");
  return lambdaAt(penaltyOrder(degree), 2.0 * kPi * cutoffHz / frameRate);
}

double smoothingSplineCutoffHz(int degree, double frameRate, double lambda)
{
  checkSmoothingSplineOptions({degree, SmoothingSplineMode::Gcv, 0.0, 1.0});
  checkRate(frameRate);
  if (!(lambda > 0.0))
    return 0.5 * frameRate;
  const int m = penaltyOrder(degree);
  double lo = 1e-9, hi = kPi;  // lambdaAt decreases with ω
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (lambdaAt(m, mid) > lambda ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi) * frameRate / (2.0 * kPi);
}

SmoothingSplineFit smoothingSpline(const Eigen::Ref<const Eigen::MatrixXd>& samples, double frameRate,
                                   const SmoothingSplineOptions& options)
{
  checkSmoothingSplineOptions(options);
  checkRate(frameRate);
  if (!samples.allFinite())
    throw InvalidArgument("smoothing spline: samples must be finite");
  SmoothingSplineFit fit;
  const Eigen::Index n = samples.rows();
  const int m = penaltyOrder(options.degree);
  if (n < minSmoothingSplineRunLength(options.degree) || samples.cols() == 0) {
    fit.smoothed = samples;
    fit.degreesOfFreedom = static_cast<double>(n);
    return fit;
  }
  const ReinschSystem system(samples, m);
  const double count = static_cast<double>(n);
  const double variance = options.errorVariance;
  const auto gcv = [count](const ReinschSystem::Evaluation& e) {
    const double t = e.trace / count;
    return t > 0.0 ? (e.rss / count) / (t * t) : std::numeric_limits<double>::infinity();
  };
  const auto risk = [count, variance](const ReinschSystem::Evaluation& e) {
    return e.rss / count - 2.0 * variance * e.trace / count + variance;
  };
  const auto score = [&](const ReinschSystem::Evaluation& e) {
    return options.mode == SmoothingSplineMode::ErrorVariance ? risk(e) : gcv(e);
  };

  double lambda = 0.0;
  if (options.mode == SmoothingSplineMode::Cutoff) {
    lambda = smoothingSplineLambda(options.degree, frameRate, options.cutoffHz);
  } else {
    // Scan log λ, then golden-section search around the best scan point (GCV can have
    // several local minima, so a bracketing search alone could settle on the wrong one).
    const double logLow = std::log(lambdaAt(m, 2.0 * kPi * kHighestCutoff));
    const double logHigh = std::log(lambdaAt(m, 2.0 * kPi * kLowestCutoff));
    const double step = (logHigh - logLow) / (kScanPoints - 1);
    const auto at = [&](double logLambda) { return score(system.evaluate(std::exp(logLambda), nullptr)); };
    int best = 0;
    double bestScore = std::numeric_limits<double>::infinity();
    for (int i = 0; i < kScanPoints; ++i) {
      const double s = at(logLow + step * i);
      if (s < bestScore) {
        bestScore = s;
        best = i;
      }
    }
    double a = logLow + step * std::max(0, best - 1);
    double b = logLow + step * std::min(kScanPoints - 1, best + 1);
    const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
    double x1 = b - ratio * (b - a), x2 = a + ratio * (b - a);
    double f1 = at(x1), f2 = at(x2);
    for (int i = 0; i < kGoldenSteps; ++i) {
      if (f1 < f2) {
        b = x2;
        x2 = x1;
        f2 = f1;
        x1 = b - ratio * (b - a);
        f1 = at(x1);
      } else {
        a = x1;
        x1 = x2;
        f1 = f2;
        x2 = a + ratio * (b - a);
        f2 = at(x2);
      }
    }
    double logLambda = f1 < f2 ? x1 : x2;
    if (std::min(f1, f2) > bestScore)
      logLambda = logLow + step * best;
    lambda = std::exp(logLambda);
  }
  const ReinschSystem::Evaluation e = system.evaluate(lambda, &fit.smoothed);
  fit.lambda = lambda;
  fit.equivalentCutoffHz = smoothingSplineCutoffHz(options.degree, frameRate, lambda);
  fit.degreesOfFreedom = count - e.trace;
  fit.criterion = score(e);
  return fit;
}

} // namespace mocap
