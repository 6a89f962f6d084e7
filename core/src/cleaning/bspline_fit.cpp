#include "mocap/cleaning/bspline_fit.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <type_traits>

namespace mocap {

namespace {

constexpr int kMaxBasis = kMaxBSplineDegree + 1;
constexpr double kMinSpanFrames = 1.5;

double binomial(int n, int k)
{
  double c = 1.0;
  for (int i = 1; i <= k; ++i)
    c = c * static_cast<double>(n - k + i) / static_cast<double>(i);
  return c;
}

// Cox–de Boor (Piegl & Tiller, algorithm A2.2): the degree + 1 basis functions that do not vanish
// on span `span` (knots[span] ≤ t < knots[span + 1]), written to `values`.
void basisFunctions(const std::vector<double>& knots, Eigen::Index span, int degree, double t, double* values)
{
  std::array<double, kMaxBasis> left{};
  std::array<double, kMaxBasis> right{};
  values[0] = 1.0;
  for (int j = 1; j <= degree; ++j) {
    const auto uj = static_cast<std::size_t>(j);
    left[uj] = t - knots[static_cast<std::size_t>(span + 1 - j)];
    right[uj] = knots[static_cast<std::size_t>(span + j)] - t;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const auto ur = static_cast<std::size_t>(r);
      const double temp = values[r] / (right[ur + 1] + left[uj - ur]);
      values[r] = saved + right[ur + 1] * temp;
      saved = left[uj - ur] * temp;
    }
    values[j] = saved;
  }
}

// Bᵀy for K columns at once: column c of the samples is y[c · yStride + i]; control j's sum for
// column c goes to out[j · outStride + c]. Samples come in span order, so the (degree + 1) · K sums
// of one span stay local and are stored once per span (no store-to-load chains). The sums of one
// column are contiguous (acc[c][r]) so that vector code loads exactly what it stored.
template <int P, int K>
void accumulateSpans(const double* basis, const Eigen::Index* first, Eigen::Index n, const double* y,
                     Eigen::Index yStride, double* out, Eigen::Index outStride)
{
  // Fixed-size and never address-taken, so the (P + 1) · K sums stay in registers.
  using Sums = Eigen::Matrix<double, P + 1, K>;
  Sums acc = Sums::Zero();
  Eigen::Index current = first[0];
  for (Eigen::Index i = 0; i <= n; ++i) {
    if (i == n || first[i] != current) {
      for (int r = 0; r <= P; ++r)
        for (int c = 0; c < K; ++c)
          out[(current + r) * outStride + c] += acc(r, c);
      if (i == n)
        break;
      acc.setZero();
      current = first[i];
    }
    const Eigen::Map<const Eigen::Matrix<double, P + 1, 1>> values(basis + i * (P + 1));
    for (int c = 0; c < K; ++c)
      acc.col(c) += values * y[c * yStride + i];
  }
}

// True when every sample is finite: x · 0 is 0 for a finite x and NaN otherwise, and the sum is
// vectorised where allFinite's early-exit test is one scalar compare per element.
bool allSamplesFinite(const Eigen::Ref<const Eigen::MatrixXd>& samples)
{
  return (samples.array() * 0.0).sum() == 0.0;
}

// The curve at every sample for K columns (eq 11): out[c · outStride + i] = Σ_r B_r(t_i) ·
// controls[(first_i + r) · controlStride + c].
template <int P, int K>
void evaluateCurve(const double* basis, const Eigen::Index* first, Eigen::Index n, const double* controls,
                   Eigen::Index controlStride, double* out, Eigen::Index outStride)
{
  for (Eigen::Index i = 0; i < n; ++i) {
    const double* values = basis + i * (P + 1);
    const double* local = controls + first[i] * controlStride;
    for (int c = 0; c < K; ++c) {
      double v = 0.0;
      for (int r = 0; r <= P; ++r)
        v += values[r] * local[r * controlStride + c];
      out[c * outStride + i] = v;
    }
  }
}

// Calls f(std::integral_constant<int, degree>{}) so the kernels get a compile-time degree.
template <typename F>
void withDegree(int degree, F&& f)
{
  switch (degree) {
  case 2: f(std::integral_constant<int, 2>{}); break;
  case 3: f(std::integral_constant<int, 3>{}); break;
  case 4: f(std::integral_constant<int, 4>{}); break;
  case 5: f(std::integral_constant<int, 5>{}); break;
  case 6: f(std::integral_constant<int, 6>{}); break;
  default: f(std::integral_constant<int, 7>{}); break;
  }
}

// Coefficients of the uniform blending functions of eq 12 as polynomials in t:
// F_{k,n}(t) = Σ_d coefficient[k][d] tᵈ, expanded once per degree from eq 12's sum (the integer
// sums are exact in doubles up to n = 7; one rounding when divided by n!). O(n³) once per degree.
using UniformPolynomials = std::array<std::array<double, kMaxBasis>, kMaxBasis>;

UniformPolynomials uniformPolynomials(int n)
{
  UniformPolynomials coefficient{};
  double factorial = 1.0;
  for (int i = 2; i <= n; ++i)
    factorial *= static_cast<double>(i);
  for (int k = 0; k <= n; ++k) {
    auto& c = coefficient[static_cast<std::size_t>(k)];
    for (int j = 0; j <= n - k; ++j) {
      // (−1)ʲ C(n + 1, j) (t + a)ⁿ with a = n − k − j, expanded by the binomial theorem.
      const double sign = (j % 2 == 0) ? 1.0 : -1.0;
      const double a = static_cast<double>(n - k - j);
      for (int d = 0; d <= n; ++d)
        c[static_cast<std::size_t>(d)] += sign * binomial(n + 1, j) * binomial(n, d) * std::pow(a, n - d);
    }
    for (double& value : c)
      value /= factorial;
  }
  return coefficient;
}

const UniformPolynomials& uniformPolynomialsOf(int n)
{
  static const std::array<UniformPolynomials, kMaxBasis> all = [] {
    std::array<UniformPolynomials, kMaxBasis> table{};
    for (int d = kMinBSplineDegree; d <= kMaxBSplineDegree; ++d)
      table[static_cast<std::size_t>(d)] = uniformPolynomials(d);
    return table;
  }();
  return all[static_cast<std::size_t>(n)];
}

// The P + 1 basis values of an interior span at t ∈ [0, 1] (eq 12 by Horner's rule, column d of
// `coefficient` holding the tᵈ coefficients): on spans whose 2P surrounding knots are all uniform,
// Cox–de Boor reduces to these polynomials, without its chain of divisions.
template <int P>
Eigen::Matrix<double, P + 1, 1> uniformBasis(const Eigen::Matrix<double, P + 1, P + 1>& coefficient, double t)
{
  Eigen::Matrix<double, P + 1, 1> values = coefficient.col(P);
#pragma GCC unroll 8  // (unrolled, the P + 1 values stay in registers)
  for (int d = P - 1; d >= 0; --d)
    values = values * t + coefficient.col(d);
  return values;
}

} // namespace

void checkBSplineFitOptions(const BSplineFitOptions& options)
{
  if (options.degree < kMinBSplineDegree || options.degree > kMaxBSplineDegree)
    throw InvalidArgument("B-spline degree must be " + std::to_string(kMinBSplineDegree) + ".." +
                          std::to_string(kMaxBSplineDegree) + " (3 = cubic, the paper's third order), not " +
                          std::to_string(options.degree));
  if (!std::isfinite(options.knotSpacing) || options.knotSpacing < 1.0)
    throw InvalidArgument("B-spline knot spacing must be a finite number of frames ≥ 1, not " +
                          std::to_string(options.knotSpacing));
}

double uniformBSplineBasis(int k, int n, double t)
{
  if (n < 0 || k < 0 || k > n)
    throw InvalidArgument("uniform B-spline basis needs 0 ≤ k ≤ n");
  double sum = 0.0;
  for (int j = 0; j <= n - k; ++j) {
    const double term = binomial(n + 1, j) * std::pow(t + static_cast<double>(n - k - j), n);
    sum += (j % 2 == 0) ? term : -term;
  }
  double factorial = 1.0;
  for (int i = 2; i <= n; ++i)
    factorial *= static_cast<double>(i);
  return sum / factorial;
}

BSplineFitter::BSplineFitter(Eigen::Index sampleCount, const BSplineFitOptions& options)
    : m_sampleCount(sampleCount), m_degree(options.degree)
{
  checkBSplineFitOptions(options);
  const int p = m_degree;
  if (sampleCount < minBSplineRunLength(p))
    throw InvalidArgument("a degree-" + std::to_string(p) + " B-spline fit needs at least " +
                          std::to_string(minBSplineRunLength(p)) + " samples, got " +
                          std::to_string(sampleCount));
  const Eigen::Index n = sampleCount;
  const double length = static_cast<double>(n - 1);
  // Spans shorter than 1.5 frames make the high-degree fits ill-conditioned (the condition number
  // of the basis grows past 1e10 for degree 7 as spans approach one frame); at ≥ 1.5 it stays
  // below 2e4 for every degree.
  const auto spans = static_cast<Eigen::Index>(std::round(length / options.knotSpacing));
  const auto longest = std::min(n - p - 1, static_cast<Eigen::Index>(std::floor(length / kMinSpanFrames)));
  m_spanCount = std::clamp(spans, Eigen::Index{1}, std::max(Eigen::Index{1}, longest));
  const Eigen::Index s = m_spanCount;
  const Eigen::Index m = s + p;  // control points
  const double h = length / static_cast<double>(s);

  std::vector<double> knots(static_cast<std::size_t>(m + p + 1), length);
  for (Eigen::Index j = 0; j < s; ++j)
    knots[static_cast<std::size_t>(p + j)] = static_cast<double>(j) * h;
  for (int j = 0; j < p; ++j)
    knots[static_cast<std::size_t>(j)] = 0.0;

  m_basis.resize(n, p + 1);
  m_firstControl.resize(static_cast<std::size_t>(n));
  BandedCholesky::Band normal = BandedCholesky::Band::Zero(m - 2, p + 1);
  m_startCoupling = Eigen::VectorXd::Zero(m - 2);
  m_endCoupling = Eigen::VectorXd::Zero(m - 2);
  withDegree(p, [&](auto degree) {
    constexpr int P = decltype(degree)::value;
    using Values = Eigen::Matrix<double, P + 1, 1>;
    Eigen::Matrix<double, P + 1, P + 1> polynomials;
    for (int k = 0; k <= P; ++k)
      for (int d = 0; d <= P; ++d)
        polynomials(k, d) = uniformPolynomialsOf(P)[static_cast<std::size_t>(k)][static_cast<std::size_t>(d)];
    // Span j's knots j + 1 .. j + 2P (of the knot vector) are uniform for P − 1 ≤ j ≤ S − P.
    const Eigen::Index firstUniform = P - 1, lastUniform = s - P;
    // Products of one span's basis values (fixed-size, so they stay in registers), added to the
    // band once per span.
    Eigen::Matrix<double, P + 1, P + 1> products;
    Eigen::Index current = -1;
    const auto flush = [&] {
      // Normal equations of the inner controls 1..m−2 (the end controls are pinned), and how each
      // inner control couples to the pinned ones (moved to the right-hand side when fitting).
      if (current >= 1 && current + P <= m - 2) {
        // A span away from the pinned controls (nearly all): every product goes to the band,
        // without the tests below (which cost more than the additions).
        double* band = normal.data() + (current - 1) * (P + 1);  // row current − 1, row-major
        for (int r = 0; r <= P; ++r)
          for (int q = 0; q <= r; ++q)
            band[r * (P + 1) + (r - q)] += products(r, q);
        return;
      }
      for (int r = 0; r <= P; ++r) {
        const Eigen::Index a = current + r;
        if (a < 1 || a > m - 2)
          continue;
        for (int q = 0; q <= r; ++q)
          if (current + q >= 1)
            normal(a - 1, r - q) += products(r, q);
        if (current == 0)
          m_startCoupling(a - 1) += products(r, 0);
        if (current + P == m - 1)
          m_endCoupling(a - 1) += products(r, P);
      }
    };
    // Two passes: the basis values of every sample first, then the span sums of their products.
    // Each sample's values are a chain of dependent operations (Horner's rule) and the samples
    // are independent, so in a loop of their own the chains of neighbouring samples overlap;
    // together with the products they waited on each other.
    // A multiplication, not a division per sample; a sample on a knot may then fall in the span
    // before it, where the basis has the same values (the spline is continuous there).
    const double perFrame = 1.0 / h;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double t = static_cast<double>(i);
      const double spanPosition = t * perFrame;
      // t / h ≥ 0, so truncation is the floor.
      const auto spanIndex = std::min(s - 1, static_cast<Eigen::Index>(spanPosition));
      Eigen::Map<Values> row(m_basis.data() + i * (P + 1));
      if (spanIndex >= firstUniform && spanIndex <= lastUniform)
        row = uniformBasis<P>(polynomials, spanPosition - static_cast<double>(spanIndex));
      else
        basisFunctions(knots, P + spanIndex, P, t, row.data());
      m_firstControl[static_cast<std::size_t>(i)] = spanIndex;
    }
    for (Eigen::Index i = 0; i < n; ++i) {
      const Values values = Eigen::Map<const Values>(m_basis.data() + i * (P + 1));
      const Eigen::Index spanIndex = m_firstControl[static_cast<std::size_t>(i)];
      if (spanIndex != current) {
        if (current >= 0)
          flush();
        current = spanIndex;
        products.noalias() = values * values.transpose();  // (assigned: no zeroing per span)
      } else {
        products.noalias() += values * values.transpose();
      }
    }
    flush();
  });
  m_normal = BandedCholesky(std::move(normal));
}

BandedCholesky::Band BSplineFitter::solve(const Eigen::Ref<const Eigen::MatrixXd>& samples) const
{
  if (samples.rows() != m_sampleCount)
    throw InvalidArgument("B-spline fit prepared for " + std::to_string(m_sampleCount) + " samples, got " +
                          std::to_string(samples.rows()));
  if (!allSamplesFinite(samples))
    throw InvalidArgument("B-spline fit: samples must be finite");
  const int p = m_degree;
  const Eigen::Index n = m_sampleCount;
  const Eigen::Index m = controlPointCount();
  const Eigen::Index k = samples.cols();
  // Bᵀy for every control at once (row-major: the k columns of one control side by side), then
  // the pinned end controls' share is taken out of the inner rows.
  BandedCholesky::Band controls = BandedCholesky::Band::Zero(m, k);
  double* full = controls.data();
  const double* y = samples.data();
  const Eigen::Index yStride = samples.outerStride();
  withDegree(p, [&](auto degree) {
    constexpr int P = decltype(degree)::value;
    if (k == 3)
      accumulateSpans<P, 3>(m_basis.data(), m_firstControl.data(), n, y, yStride, full, k);
    else
      for (Eigen::Index c = 0; c < k; ++c)
        accumulateSpans<P, 1>(m_basis.data(), m_firstControl.data(), n, y + c * yStride, yStride, full + c,
                              k);
  });
  BandedCholesky::Band inner = controls.middleRows(1, m - 2);
  inner -= m_startCoupling * samples.row(0) + m_endCoupling * samples.row(n - 1);
  m_normal.solveInPlace(inner);
  controls.middleRows(1, m - 2) = inner;
  controls.row(0) = samples.row(0);
  controls.row(m - 1) = samples.row(n - 1);
  return controls;
}

Eigen::MatrixXd BSplineFitter::controlPoints(const Eigen::Ref<const Eigen::MatrixXd>& samples) const
{
  return solve(samples);
}

Eigen::MatrixXd BSplineFitter::fit(const Eigen::Ref<const Eigen::MatrixXd>& samples) const
{
  Eigen::MatrixXd result(m_sampleCount, samples.cols());
  fit(samples, result);
  return result;
}

void BSplineFitter::fit(const Eigen::Ref<const Eigen::MatrixXd>& samples,
                        Eigen::Ref<Eigen::MatrixXd> result) const
{
  if (result.rows() != samples.rows() || result.cols() != samples.cols())
    throw InvalidArgument("B-spline fit: the result must have the samples' shape");
  const BandedCholesky::Band controls = solve(samples);
  const Eigen::Index k = samples.cols();
  double* out = result.data();
  const Eigen::Index outStride = result.outerStride();
  withDegree(m_degree, [&](auto degree) {
    constexpr int P = decltype(degree)::value;
    if (k == 3)
      evaluateCurve<P, 3>(m_basis.data(), m_firstControl.data(), m_sampleCount, controls.data(), k, out,
                          outStride);
    else
      for (Eigen::Index c = 0; c < k; ++c)
        evaluateCurve<P, 1>(m_basis.data(), m_firstControl.data(), m_sampleCount, controls.data() + c, k,
                            out + c * outStride, outStride);
  });
}

Eigen::MatrixXd fitBSpline(const Eigen::Ref<const Eigen::MatrixXd>& samples, const BSplineFitOptions& options)
{
  checkBSplineFitOptions(options);
  if (!allSamplesFinite(samples))
    throw InvalidArgument("B-spline fit: samples must be finite");
  if (samples.rows() < minBSplineRunLength(options.degree))
    return samples;
  return BSplineFitter(samples.rows(), options).fit(samples);
}

} // namespace mocap
