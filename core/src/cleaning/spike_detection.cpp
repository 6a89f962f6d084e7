#include "mocap/cleaning/spike_detection.h"

#include "mocap/base/enum_table.h"
#include "mocap/base/error.h"
#include "mocap/model/valid_runs.h"
#include "mocap/base/length_unit.h"
#include "mocap/model/marker_points.h"

#include "median_networks.h"
#if defined(MOCAP_AVX2_KERNELS)
#include "spike_kernels_avx2.h"
#endif

#include <Eigen/Dense>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <string>
#include <utility>

namespace mocap {

namespace {

using Trajectory = Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>;

// Median length of a 3-D vector of independent unit normals: turns a median residual length
// into a per-axis standard deviation.
constexpr double kMedianLengthPerSigma = 1.5382;

struct Run
{
  Eigen::Index first = 0;
  Eigen::Index last = 0;  // inclusive
  [[nodiscard]] Eigen::Index size() const { return last - first + 1; }
};

// The valid runs (findValidRuns) as inclusive windows, the form the detectors work on.
std::vector<Run> validRuns(const Eigen::Ref<const ValidMask>& valid)
{
  std::vector<Run> runs;
  for (const ValidRun& run : findValidRuns(valid))
    runs.push_back({run.first, run.first + run.length - 1});
  return runs;
}

// Median of [begin, end) of a sorted range; the mean of the two middle values for an even count.
double sortedMedian(const double* begin, const double* end)
{
  const auto n = end - begin;
  return n % 2 == 1 ? begin[n / 2] : 0.5 * (begin[n / 2 - 1] + begin[n / 2]);
}

// The same medians for kLanes neighbouring windows at once (one window per lane of a vector
// register): each lane goes through the very operations of the scalar code, so the results are
// the scalar results bit for bit. std::min(a, b) is minsd with b first and std::max(a, b) maxsd
// with b first, which is what the vector forms below do (the same answer for equal or signed zeros).
#if defined(__SSE2__)
constexpr Eigen::Index kLanes = 2;
struct Lanes
{
  __m128d v;
};
Lanes loadLanes(const double* p)
{
  return {_mm_loadu_pd(p)};
}
double lane(const Lanes& a, std::size_t l)
{
  alignas(16) double values[kLanes];
  _mm_store_pd(values, a.v);
  return values[l];
}
Lanes makeLanes(double first, double second)
{
  return {_mm_set_pd(second, first)};
}
Lanes operator+(const Lanes& a, const Lanes& b)
{
  return {_mm_add_pd(a.v, b.v)};
}
Lanes operator*(const Lanes& a, const Lanes& b)
{
  return {_mm_mul_pd(a.v, b.v)};
}
Lanes operator/(const Lanes& a, const Lanes& b)
{
  return {_mm_div_pd(a.v, b.v)};
}
Lanes squareRoot(const Lanes& a)
{
  return {_mm_sqrt_pd(a.v)};
}
void storeLanes(double* p, const Lanes& a)
{
  _mm_storeu_pd(p, a.v);
}
Lanes operator-(const Lanes& a, const Lanes& b)
{
  return {_mm_sub_pd(a.v, b.v)};
}
Lanes operator*(double a, const Lanes& b)
{
  return {_mm_mul_pd(_mm_set1_pd(a), b.v)};
}
Lanes operator*(const Lanes& a, double b)
{
  return {_mm_mul_pd(a.v, _mm_set1_pd(b))};
}
void order(Lanes& a, Lanes& b)
{
  const __m128d low = _mm_min_pd(b.v, a.v);
  b.v = _mm_max_pd(b.v, a.v);
  a.v = low;
}
#else
constexpr Eigen::Index kLanes = 2;
struct Lanes
{
  std::array<double, static_cast<std::size_t>(kLanes)> v;
};
Lanes loadLanes(const double* p)
{
  return {{p[0], p[1]}};
}
double lane(const Lanes& a, std::size_t l)
{
  return a.v[l];
}
template <typename Op>
Lanes each(const Lanes& a, const Lanes& b, Op op)
{
  Lanes r;
  for (std::size_t l = 0; l < static_cast<std::size_t>(kLanes); ++l)
    r.v[l] = op(a.v[l], b.v[l]);
  return r;
}
Lanes makeLanes(double first, double second)
{
  return {{first, second}};
}
Lanes operator+(const Lanes& a, const Lanes& b)
{
  return each(a, b, [](double x, double y) { return x + y; });
}
Lanes operator*(const Lanes& a, const Lanes& b)
{
  return each(a, b, [](double x, double y) { return x * y; });
}
Lanes operator/(const Lanes& a, const Lanes& b)
{
  return each(a, b, [](double x, double y) { return x / y; });
}
Lanes squareRoot(const Lanes& a)
{
  return each(a, a, [](double x, double /*unused*/) { return std::sqrt(x); });
}
void storeLanes(double* p, const Lanes& a)
{
  p[0] = a.v[0];
  p[1] = a.v[1];
}
Lanes operator-(const Lanes& a, const Lanes& b)
{
  return each(a, b, [](double x, double y) { return x - y; });
}
Lanes operator*(double a, const Lanes& b)
{
  return each({{a, a}}, b, [](double x, double y) { return x * y; });
}
Lanes operator*(const Lanes& a, double b)
{
  return each(a, {{b, b}}, [](double x, double y) { return x * y; });
}
void order(Lanes& a, Lanes& b)
{
  for (std::size_t l = 0; l < static_cast<std::size_t>(kLanes); ++l)
    order(a.v[l], b.v[l]);
}
#endif

// Calls f(std::integral_constant<std::size_t, k>{}) for k = 0..N−1, unrolled at compile time so
// the lanes of the networks below stay in registers (-O2 does not unroll these loops).
template <typename F, std::size_t... K>
void unrolledSequence(F& f, std::index_sequence<K...> /*unused*/)
{
  (f(std::integral_constant<std::size_t, K>{}), ...);
}

template <std::size_t N, typename F>
void unrolled(F&& f)
{
  unrolledSequence(f, std::make_index_sequence<N>{});
}

// |sample − estimate|² for the kLanes samples from frame i (the estimate one Lanes per axis),
// the squares summed as Eigen's norm() sums a 3-vector, x² + (y² + z²), so each lane's square
// root is the scalar norm bit for bit. The roots are taken later, a whole run at a time
// (rootsOf): one root per call here waited out the square root's latency every two samples,
// a fifth of the detector's time.
Lanes squaredDistances(const Trajectory& xyz, Eigen::Index i, const std::array<Lanes, 3>& estimate)
{
  std::array<Lanes, 3> d;
  for (Eigen::Index c = 0; c < 3; ++c)
    d[static_cast<std::size_t>(c)] = loadLanes(xyz.col(c).data() + i) - estimate[static_cast<std::size_t>(c)];
  return d[0] * d[0] + (d[1] * d[1] + d[2] * d[2]);
}

// r[k] = sqrt(r[k]) / divisor[k] for k in [from, to) (divisor null: 1), in independent lanes,
// so the roots overlap. The same correctly rounded operations as one sample at a time.
void rootsOf(double* r, const double* divisor, Eigen::Index from, Eigen::Index to)
{
  Eigen::Index k = from;
  for (; k + kLanes <= to; k += kLanes) {
    const Lanes root = squareRoot(loadLanes(r + k));
    storeLanes(r + k, divisor ? root / loadLanes(divisor + k) : root);
  }
  for (; k < to; ++k)
    r[k] = divisor ? std::sqrt(r[k]) / divisor[k] : std::sqrt(r[k]);
}

Lanes middle(const Lanes& a, const Lanes& b)
{
  return 0.5 * (a + b);
}

// Median of a few values (reorders them): insertion sort beats selection below ~16 values.
double smallMedian(double* begin, double* end)
{
  for (double* a = begin + 1; a < end; ++a) {
    const double value = *a;
    double* b = a;
    for (; b > begin && *(b - 1) > value; --b)
      *b = *(b - 1);
    *b = value;
  }
  return sortedMedian(begin, end);
}

// The window of `width` samples around `i` inside `run`, shifted inward at the run's ends so it
// keeps its width (a sample at a run end is judged by extrapolation from one side).
Run windowAround(const Run& run, Eigen::Index i, Eigen::Index halfWidth)
{
  const Eigen::Index width = 2 * halfWidth + 1;
  if (run.size() <= width)
    return run;
  const Eigen::Index first = std::clamp(i - halfWidth, run.first, run.last - width + 1);
  return {first, first + width - 1};
}

} // namespace

void checkSpikeOptions(const SpikeOptions& options)
{
  if (!(std::isfinite(options.factor) && options.factor > 0.0))
    throw InvalidArgument("spike factor must be a finite number > 0, not " + std::to_string(options.factor));
  if (!(std::isfinite(options.threshold) && options.threshold > 0.0))
    throw InvalidArgument("spike threshold must be a finite number > 0, not " +
                          std::to_string(options.threshold));
  if (!(std::isfinite(options.noiseFloor) && options.noiseFloor >= 0.0))
    throw InvalidArgument("spike noise floor must be a finite number >= 0, not " +
                          std::to_string(options.noiseFloor));
  if (options.maxPasses < 1 || options.maxPasses > 100)
    throw InvalidArgument("spike detection passes must be in 1..100, not " + std::to_string(options.maxPasses));
}

namespace {

// Eqs 8-9 on one run P_0..P_n.
void detectPaper(const Trajectory& xyz, const Run& run, double factor, std::vector<Eigen::Index>& flags)
{
  if (run.size() < 3)
    return;
  const Eigen::Index n = run.size() - 1;  // segments
  Eigen::VectorXd segment(n);
  for (Eigen::Index s = 0; s < n; ++s)
    segment(s) = (xyz.row(run.first + s + 1) - xyz.row(run.first + s)).norm();
  const double k = segment.sum() / static_cast<double>(n);  // eq 8
  if (!(k > 0.0))
    return;  // a still marker: no segment can stand out
  const double limit = factor * k;
  for (Eigen::Index i = 1; i < n; ++i)
    if (segment(i - 1) >= limit && segment(i) >= limit)  // eq 9
      flags.push_back(run.first + i);
}

// The robust detector's fixed windows and cut-offs, chosen on the three real takes named in the
// header: a wider fit window follows fast facial motion worse, a narrower one keeps too few
// samples once a block of 3 is left out.
constexpr Eigen::Index kLineHalfWidth = 3;       // stage 1: 7 samples; a block of 3 cannot move a median
constexpr Eigen::Index kQuadraticHalfWidth = 4;  // stage 2: 9 samples
constexpr Eigen::Index kScaleHalfWidth = 5;      // robust scale: median over 11 samples
constexpr double kSuspectThreshold = 3.0;        // stage 1 cut-off, in robust standard deviations
constexpr std::size_t kMaxLeftOut = 4;           // suspects left out of one stage-2 fit
constexpr double kRunEndScaleWeight = 0.5;       // see runEndSigma
constexpr Eigen::Index kMinRobustRun = 5;        // shorter runs have too few samples to judge one

// Buffers reused across the runs of a trajectory.
struct RobustWork
{
  Eigen::VectorXd lineResidual;
  Eigen::VectorXd fitResidual;
  // The local scale; while stage 2 runs (stage 1's scale is used up by then), the deviations of
  // the interior's predictions until fitResidual is rooted: a buffer of its own cost a fresh
  // allocation, and the page faults of its memory, per marker.
  Eigen::VectorXd sigma;
  std::vector<char> suspect;
};

// Stage 1 (below) for sample i, its window shifted inward at the run ends.
void medianLineResidualAt(const Trajectory& xyz, const Run& run, Eigen::Index i, Eigen::VectorXd& r)
{
  std::array<double, 2 * kLineHalfWidth + 1> values{};
  const Run w = windowAround(run, i, kLineHalfWidth);
  const auto count = static_cast<std::size_t>(w.size());
  Eigen::RowVector3d level;
  for (Eigen::Index c = 0; c < 3; ++c) {
    for (Eigen::Index j = w.first; j < w.last; ++j)
      values[static_cast<std::size_t>(j - w.first)] = xyz(j + 1, c) - xyz(j, c);
    const double slope =
        count == 7 ? median6(values.data()) : smallMedian(values.data(), values.data() + count - 1);
    for (Eigen::Index j = w.first; j <= w.last; ++j)
      values[static_cast<std::size_t>(j - w.first)] = xyz(j, c) - slope * static_cast<double>(j - i);
    level(c) = count == 7 ? median7(values.data()) : smallMedian(values.data(), values.data() + count);
  }
  r(i - run.first) = (xyz.row(i) - level).norm();
}

// Interior samples i..i + kLanes − 1 (full 7-sample windows), one window per lane: the same
// values through the same networks as medianLineResidualAt.
void medianLineResidualsAt(const Trajectory& xyz, const Run& run, Eigen::Index i, Eigen::VectorXd& r)
{
  constexpr Eigen::Index width = 2 * kLineHalfWidth + 1;
  std::array<Lanes, 3> level{};
  for (Eigen::Index c = 0; c < 3; ++c) {
    const double* x = xyz.col(c).data() + (i - kLineHalfWidth);  // x[l + k]: sample k of lane l's window
    std::array<Lanes, width> values;
    unrolled<width - 1>([&](auto k) { values[k] = loadLanes(x + k + 1) - loadLanes(x + k); });
    const Lanes slope = median6(values.data());
    unrolled<width>([&](auto k) {
      values[k] = loadLanes(x + k) - slope * static_cast<double>(static_cast<Eigen::Index>(k()) - kLineHalfWidth);
    });
    level[static_cast<std::size_t>(c)] = median7(values.data());
  }
  storeLanes(r.data() + (i - run.first), squaredDistances(xyz, i, level));  // rooted by the caller
}

// Whether the four-lane AVX2 kernels run: the CPU has AVX2 and MOCAP_NO_AVX2 is not set (which
// rules them out, e.g. to compare the two paths, whose results are the same bit for bit).
bool useAvx2Kernels()
{
#if defined(MOCAP_AVX2_KERNELS)
  static const bool use = __builtin_cpu_supports("avx2") && std::getenv("MOCAP_NO_AVX2") == nullptr;
  return use;
#else
  return false;
#endif
}

// Stage 1: a local line fitted by medians per axis over 7 samples (slope: median of the first
// differences; level at i: median of the samples detrended to i). Up to 3 bad samples in the
// window cannot move it, so they stand out, but it rounds off sharp turns, which stage 2 undoes.
void medianLineResiduals(const Trajectory& xyz, const Run& run, Eigen::VectorXd& r)
{
  Eigen::Index i = run.first;
  if (run.size() > 2 * kLineHalfWidth + 1) {
    // Interior samples, whose windows are centred, kLanes at a time.
    for (; i < run.first + kLineHalfWidth; ++i)
      medianLineResidualAt(xyz, run, i, r);
    const Eigen::Index lanesFrom = i;
#if defined(MOCAP_AVX2_KERNELS)
    if (useAvx2Kernels())
      i = run.first + avx2::squaredLineResiduals(xyz.col(0).data() + run.first, xyz.col(1).data() + run.first,
                                                 xyz.col(2).data() + run.first, i - run.first,
                                                 run.last - kLineHalfWidth + 1 - run.first, r.data());
#endif
    for (; i + kLanes - 1 <= run.last - kLineHalfWidth; i += kLanes)
      medianLineResidualsAt(xyz, run, i, r);
    rootsOf(r.data(), nullptr, lanesFrom - run.first, i - run.first);
  }
  for (; i <= run.last; ++i)
    medianLineResidualAt(xyz, run, i, r);
}

// Tricube-weighted quadratic fits over a window of 9 samples that leave out the sample at `centre`
// (window index 0..8; off the middle only near a run end). The sums and the prediction filter
// without suspects depend on nothing but the centre, so they are computed once.
constexpr int kWindow = 2 * kQuadraticHalfWidth + 1;

struct LeaveOneOutFit
{
  std::array<double, kWindow> weight{};              // 0 at the centre
  std::array<Eigen::Vector3d, kWindow> phi{};        // (1, t, t²), t = index − centre
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();  // Σ w φφ'
  Eigen::Matrix3d noise = Eigen::Matrix3d::Zero();   // Σ w² φφ'
  std::array<double, kWindow> filter{};              // prediction = Σ filter · sample
  double variance = 0.0;                             // of the prediction, for unit noise
};

double tricube(double u)
{
  const double a = 1.0 - u * u * u;
  return a * a * a;
}

// The value at t = 0 of the weighted least-squares quadratic with these sums is g'·Σ wφx with
// g = N⁻¹e0, and its variance for unit noise is g'Qg (sandwich form: the weights are not inverse
// variances). Returns g.
Eigen::Vector3d leaveOutGain(const Eigen::Matrix3d& n)
{
  // First column of the inverse of the symmetric 3×3 N by cofactors: a fixed handful of flops.
  const Eigen::Vector3d cofactor(n(1, 1) * n(2, 2) - n(1, 2) * n(1, 2), n(0, 2) * n(1, 2) - n(0, 1) * n(2, 2),
                                 n(0, 1) * n(1, 2) - n(0, 2) * n(1, 1));
  return cofactor / n.col(0).dot(cofactor);
}

const std::array<LeaveOneOutFit, kWindow>& leaveOneOutFits()
{
  static const std::array<LeaveOneOutFit, kWindow> fits = [] {
    std::array<LeaveOneOutFit, kWindow> all{};
    for (int centre = 0; centre < kWindow; ++centre) {
      LeaveOneOutFit& fit = all[static_cast<std::size_t>(centre)];
      const double reach = static_cast<double>(std::max(centre, kWindow - 1 - centre) + 1);
      for (int k = 0; k < kWindow; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        const double t = static_cast<double>(k - centre);
        fit.phi[kk] = Eigen::Vector3d(1.0, t, t * t);
        fit.weight[kk] = k == centre ? 0.0 : tricube(std::abs(t) / reach);
        fit.normal += fit.weight[kk] * fit.phi[kk] * fit.phi[kk].transpose();
        fit.noise += fit.weight[kk] * fit.weight[kk] * fit.phi[kk] * fit.phi[kk].transpose();
      }
      const Eigen::Vector3d g = leaveOutGain(fit.normal);
      for (std::size_t k = 0; k < fit.filter.size(); ++k)
        fit.filter[k] = fit.weight[k] * g.dot(fit.phi[k]);
      fit.variance = g.dot(fit.noise * g);
    }
    return all;
  }();
  return fits;
}

// Prediction of sample `i` from the samples of window `w` that are neither `i` nor in `leftOut`
// (at least 3 remain), by a tricube-weighted quadratic; returns the prediction's variance for unit
// noise. For the windows of runs shorter than 9 samples.
double predictFromScratch(const Trajectory& xyz, const Run& w, Eigen::Index i, const Eigen::Index* leftOut,
                          std::size_t leftOutCount, Eigen::RowVector3d& value)
{
  const double reach = static_cast<double>(std::max(i - w.first, w.last - i) + 1);
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d noise = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d rhs = Eigen::Matrix3d::Zero();
  for (Eigen::Index j = w.first; j <= w.last; ++j) {
    if (j == i || std::find(leftOut, leftOut + leftOutCount, j) != leftOut + leftOutCount)
      continue;
    const double t = static_cast<double>(j - i);
    const double weight = tricube(std::abs(t) / reach);
    const Eigen::Vector3d phi(1.0, t, t * t);
    normal += weight * phi * phi.transpose();
    noise += weight * weight * phi * phi.transpose();
    rhs += weight * phi * xyz.row(j);
  }
  const Eigen::Vector3d g = leaveOutGain(normal);
  value = g.transpose() * rhs;
  return g.dot(noise * g);
}

// The prediction filter of `fit` without the window samples leftOut[0..count) (window indices;
// at least 4 samples remain): their terms removed from the precomputed sums. Returns the
// prediction's variance for unit noise.
double filterWithout(const LeaveOneOutFit& fit, const std::size_t* leftOut, std::size_t count,
                     std::array<double, kWindow>& filter)
{
  Eigen::Matrix3d normal = fit.normal;
  Eigen::Matrix3d noise = fit.noise;
  std::array<double, kWindow> weight = fit.weight;
  for (std::size_t l = 0; l < count; ++l) {
    const std::size_t k = leftOut[l];
    const Eigen::Matrix3d outer = fit.phi[k] * fit.phi[k].transpose();
    normal -= weight[k] * outer;
    noise -= weight[k] * weight[k] * outer;
    weight[k] = 0.0;
  }
  const Eigen::Vector3d g = leaveOutGain(normal);
  for (std::size_t k = 0; k < weight.size(); ++k)
    filter[k] = weight[k] * g.dot(fit.phi[k]);
  return g.dot(noise * g);
}

// Stage 2's filter for a centred window by the set of suspects it leaves out (bit k: window
// sample k; never the centre, at most kMaxLeftOut bits), with the prediction's standard
// deviation relative to the noise. All 2⁹ sets are computed once (40 kB), so a window with
// suspects costs what a clean one does.
struct CentredFilter
{
  std::array<double, kWindow> filter{};
  double deviation = 1.0;  // sqrt(1 + variance of the prediction)
  bool computed = false;   // false for sets with the centre or more than kMaxLeftOut suspects
};

using SuspectMask = unsigned;
constexpr SuspectMask kCentreBit = 1u << kQuadraticHalfWidth;

using CentredFilters = std::array<CentredFilter, std::size_t{1} << kWindow>;

const CentredFilters& centredFilters()
{
  static const auto table = [] {
    CentredFilters all{};
    const LeaveOneOutFit& fit = leaveOneOutFits()[static_cast<std::size_t>(kQuadraticHalfWidth)];
    for (SuspectMask mask = 0; mask < all.size(); ++mask) {
      std::array<std::size_t, kWindow> leftOut{};
      std::size_t count = 0;
      for (std::size_t k = 0; k < kWindow; ++k)
        if ((mask >> k) & 1u)
          leftOut[count++] = k;
      if ((mask & kCentreBit) != 0 || count > kMaxLeftOut)
        continue;
      CentredFilter& entry = all[mask];
      const double variance = count == 0 ? fit.variance : filterWithout(fit, leftOut.data(), count, entry.filter);
      if (count == 0)
        entry.filter = fit.filter;
      entry.deviation = std::sqrt(1.0 + variance);
      entry.computed = true;
    }
    return all;
  }();
  return table;
}

// The suspects of window `w` other than `i` that one fit leaves out: all of them, or the
// kMaxLeftOut (fewer in a short window: at least 3 samples stay for the quadratic) with the
// largest stage-1 residuals. Writes their frames to leftOut; returns how many.
std::size_t leftOutSuspects(const Run& run, Eigen::Index i, const Run& w, const RobustWork& work,
                            std::array<Eigen::Index, kWindow>& leftOut)
{
  const auto others = static_cast<std::size_t>(w.size() - 1);
  const std::size_t maxLeftOut = std::min(kMaxLeftOut, others > 3 ? others - 3 : 0);
  std::size_t count = 0;
  for (Eigen::Index j = w.first; j <= w.last; ++j)
    if (j != i && work.suspect[static_cast<std::size_t>(j - run.first)])
      leftOut[count++] = j;
  if (count > maxLeftOut) {
    const auto byResidual = [&](Eigen::Index a, Eigen::Index b) {
      return work.lineResidual(a - run.first) > work.lineResidual(b - run.first);
    };
    std::partial_sort(leftOut.begin(), leftOut.begin() + static_cast<std::ptrdiff_t>(maxLeftOut),
                      leftOut.begin() + static_cast<std::ptrdiff_t>(count), byResidual);
    std::sort(leftOut.begin(), leftOut.begin() + static_cast<std::ptrdiff_t>(maxLeftOut));
    count = maxLeftOut;
  }
  return count;
}

// Stage 2 for sample `i` and window `w` (9 samples, or the whole of a shorter run): the sample
// predicted by a tricube-weighted local quadratic without itself and without the (at most 4)
// worst stage-1 suspects of the window. The prediction error is divided by its standard
// deviation relative to the noise, sqrt(1 + var(prediction)), so extrapolations compare fairly.
double predictionResidual(const Trajectory& xyz, const Run& run, Eigen::Index i, const Run& w,
                          const RobustWork& work)
{
  std::array<Eigen::Index, kWindow> leftOut{};
  const std::size_t leftOutCount = leftOutSuspects(run, i, w, work, leftOut);
  Eigen::RowVector3d value = Eigen::RowVector3d::Zero();
  double variance = 0.0;
  if (w.size() < kWindow) {
    variance = predictFromScratch(xyz, w, i, leftOut.data(), leftOutCount, value);
  } else {
    const LeaveOneOutFit& fit = leaveOneOutFits()[static_cast<std::size_t>(i - w.first)];
    std::array<double, kWindow> filter = fit.filter;
    variance = fit.variance;
    if (leftOutCount > 0) {
      std::array<std::size_t, kWindow> inWindow{};
      for (std::size_t l = 0; l < leftOutCount; ++l)
        inWindow[l] = static_cast<std::size_t>(leftOut[l] - w.first);
      variance = filterWithout(fit, inWindow.data(), leftOutCount, filter);
    }
    for (std::size_t k = 0; k < filter.size(); ++k)
      value += filter[k] * xyz.row(w.first + static_cast<Eigen::Index>(k));
  }
  return (xyz.row(i) - value).norm() / std::sqrt(1.0 + variance);
}

// The left-out set of interior sample i's centred window, from `window` (bit k: sample
// i − 4 + k is a suspect): its suspects other than i, reduced as leftOutSuspects reduces them.
SuspectMask centredLeftOut(const Run& run, Eigen::Index i, SuspectMask window, const CentredFilters& filters,
                           const RobustWork& work)
{
  const SuspectMask mask = window & ~kCentreBit;
  if (filters[mask].computed)
    return mask;
  std::array<Eigen::Index, kWindow> leftOut{};
  const Run w{i - kQuadraticHalfWidth, i + kQuadraticHalfWidth};
  const std::size_t count = leftOutSuspects(run, i, w, work, leftOut);
  SuspectMask reduced = 0;
  for (std::size_t l = 0; l < count; ++l)
    reduced |= 1u << static_cast<unsigned>(leftOut[l] - w.first);
  return reduced;
}

// Stage 2 for interior samples i..i + kLanes − 1 (centred windows), one sample per lane, each
// with the precomputed filter of its left-out set, summed in the order predictionResidual sums
// (so the results are predictionResidual's).
void filteredResiduals(const Trajectory& xyz, const Run& run, Eigen::Index i,
                       const std::array<SuspectMask, kLanes>& leftOut, const CentredFilters& filters,
                       RobustWork& work)
{
  static_assert(kLanes == 2, "one filter per lane");
  const CentredFilter& first = filters[leftOut[0]];
  const CentredFilter& second = filters[leftOut[1]];
  std::array<Lanes, 3> value{};
  for (Eigen::Index c = 0; c < 3; ++c) {
    const double* x = xyz.col(c).data() + (i - kQuadraticHalfWidth);
    Lanes& sum = value[static_cast<std::size_t>(c)];
    unrolled<kWindow>(
        [&](auto k) { sum = sum + makeLanes(first.filter[k], second.filter[k]) * loadLanes(x + k); });
  }
  // Rooted and divided by the deviation by the caller.
  storeLanes(work.fitResidual.data() + (i - run.first), squaredDistances(xyz, i, value));
  storeLanes(work.sigma.data() + (i - run.first), makeLanes(first.deviation, second.deviation));
}

// Stage 2 for every sample of the run, each with its window shifted inward at the run ends.
// O(run length): the interior's windows go through the filter table, a rolling mask says
// which of their samples are suspects.
void quadraticResiduals(const Trajectory& xyz, const Run& run, RobustWork& work)
{
  Eigen::Index i = run.first;
  if (run.size() > kWindow) {
    const auto suspectBit = [&](Eigen::Index f) {
      return f <= run.last && work.suspect[static_cast<std::size_t>(f - run.first)] != 0 ? SuspectMask{1} : 0u;
    };
    for (; i < run.first + kQuadraticHalfWidth; ++i)
      work.fitResidual(i - run.first) =
          predictionResidual(xyz, run, i, windowAround(run, i, kQuadraticHalfWidth), work);
    SuspectMask window = 0;  // bit k: sample i − 4 + k
    for (unsigned k = 0; k < static_cast<unsigned>(kWindow); ++k)
      window |= suspectBit(run.first + static_cast<Eigen::Index>(k)) << k;
    const auto step = [&] {
      window = (window >> 1) | (suspectBit(i + 1 + kQuadraticHalfWidth) << (kWindow - 1));
      ++i;
    };
    const CentredFilters& filters = centredFilters();
    const Eigen::Index lanesFrom = i;
    work.sigma.resize(run.size());
    for (; i + kLanes - 1 <= run.last - kQuadraticHalfWidth;) {
      std::array<SuspectMask, kLanes> leftOut{};
      for (SuspectMask& mask : leftOut) {
        mask = centredLeftOut(run, i, window, filters, work);
        step();
      }
      filteredResiduals(xyz, run, i - kLanes, leftOut, filters, work);
    }
    rootsOf(work.fitResidual.data(), work.sigma.data(), lanesFrom - run.first, i - run.first);
  }
  for (; i <= run.last; ++i)
    work.fitResidual(i - run.first) =
        predictionResidual(xyz, run, i, windowAround(run, i, kQuadraticHalfWidth), work);
}

// Within 4 samples of a run end the prediction extrapolates, and in fast motion its error grows
// far beyond that of the interior samples the local scale comes from. So the same lopsided
// prediction is also made for the sample's (up to 8) inward neighbours, and the median of those
// residuals, at half weight, is a floor for its scale. Full weight leaves clean run ends alone in
// any motion but hides more real spikes next to gaps; half weight keeps fast swings of a few mm per
// frame unflagged while losing few spikes (measured on the takes named in the header).
void runEndSigma(const Trajectory& xyz, const Run& run, RobustWork& work)
{
  const Eigen::Index n = run.size();
  const Eigen::Index references = std::min<Eigen::Index>(kWindow - 1, n - kWindow);
  if (references < 1)
    return;
  std::array<double, kWindow - 1> residual{};
  for (Eigen::Index offset = 0; offset < kQuadraticHalfWidth; ++offset) {
    for (const bool atStart : {true, false}) {
      const Eigen::Index i = atStart ? run.first + offset : run.last - offset;
      for (Eigen::Index k = 1; k <= references; ++k) {
        const Eigen::Index j = atStart ? i + k : i - k;
        const Run w = atStart ? Run{run.first + k, run.first + k + kWindow - 1}
                              : Run{run.last - k - kWindow + 1, run.last - k};
        residual[static_cast<std::size_t>(k - 1)] = predictionResidual(xyz, run, j, w, work);
      }
      const double scale = kRunEndScaleWeight * smallMedian(residual.data(), residual.data() + references) /
                           kMedianLengthPerSigma;
      double& sigma = work.sigma(i - run.first);
      sigma = std::max(sigma, scale);
    }
  }
}

// Robust standard deviation around each sample: the median of `r` over 11 samples (shifted
// inward at the ends) divided by the median length of a 3-D unit normal vector, at least `floor`.
void localSigma(const Eigen::VectorXd& r, double floor, Eigen::VectorXd& sigma)
{
  constexpr Eigen::Index width = 2 * kScaleHalfWidth + 1;
  const auto toSigma = [floor](double median) { return std::max(floor, median / kMedianLengthPerSigma); };
  const Eigen::Index n = r.size();
  std::array<double, width> values{};
  if (n < width) {  // one window for the whole run
    std::copy(r.data(), r.data() + n, values.data());
    sigma.setConstant(n, toSigma(smallMedian(values.data(), values.data() + n)));
    return;
  }
  sigma.resize(n);
  Eigen::Index centre = kScaleHalfWidth;
  // Four windows at a time: the windows at c and c + 1 share 10 samples, so one middle pair of
  // those 10 gives both medians (medianWithMiddlePair), half the comparisons of two median11
  // networks. Lane 0 takes the windows at c, c + 1, lane 1 those at c + 2, c + 3.
  static_assert(kLanes == 2, "two pairs of windows");
  for (; centre + 3 < n - kScaleHalfWidth; centre += 4) {
    const double* x = r.data() + centre;
    std::array<Lanes, width - 1> shared;
    unrolled<width - 1>([&](auto k) {
      const auto at = static_cast<Eigen::Index>(k()) - (kScaleHalfWidth - 1);
      shared[k] = makeLanes(x[at], x[at + 2]);
    });
    middlePairOf10(shared.data());
    const Lanes left = medianWithMiddlePair(shared[4], shared[5], makeLanes(x[-kScaleHalfWidth], x[2 - kScaleHalfWidth]));
    const Lanes right =
        medianWithMiddlePair(shared[4], shared[5], makeLanes(x[1 + kScaleHalfWidth], x[3 + kScaleHalfWidth]));
    sigma(centre) = toSigma(lane(left, 0));
    sigma(centre + 1) = toSigma(lane(right, 0));
    sigma(centre + 2) = toSigma(lane(left, 1));
    sigma(centre + 3) = toSigma(lane(right, 1));
  }
  for (; centre + kLanes - 1 < n - kScaleHalfWidth; centre += kLanes) {
    // kLanes neighbouring windows at once, one per lane.
    const double* x = r.data() + centre - kScaleHalfWidth;
    std::array<Lanes, width> lanes;
    unrolled<width>([&](auto k) { lanes[k] = loadLanes(x + k); });
    const Lanes median = median11(lanes.data());
    for (std::size_t l = 0; l < static_cast<std::size_t>(kLanes); ++l)
      sigma(centre + static_cast<Eigen::Index>(l)) = toSigma(lane(median, l));
  }
  for (; centre < n - kScaleHalfWidth; ++centre) {
    std::copy(r.data() + centre - kScaleHalfWidth, r.data() + centre + kScaleHalfWidth + 1, values.data());
    sigma(centre) = toSigma(median11(values.data()));
  }
  sigma.head(kScaleHalfWidth).setConstant(sigma(kScaleHalfWidth));
  sigma.tail(kScaleHalfWidth).setConstant(sigma(n - 1 - kScaleHalfWidth));
}

void detectRobust(const Trajectory& xyz, const Run& run, double threshold, double floor, RobustWork& work,
                  std::vector<Eigen::Index>& flags)
{
  const Eigen::Index n = run.size();
  if (n < kMinRobustRun)
    return;
  work.lineResidual.resize(n);
  work.fitResidual.resize(n);
  work.suspect.assign(static_cast<std::size_t>(n), 0);
  medianLineResiduals(xyz, run, work.lineResidual);
  localSigma(work.lineResidual, floor, work.sigma);
  for (Eigen::Index i = 0; i < n; ++i)
    work.suspect[static_cast<std::size_t>(i)] =
        work.lineResidual(i) > kSuspectThreshold * work.sigma(i) ? 1 : 0;
  quadraticResiduals(xyz, run, work);
  localSigma(work.fitResidual, floor, work.sigma);
  runEndSigma(xyz, run, work);
  for (Eigen::Index i = 0; i < n; ++i)
    if (work.fitResidual(i) > threshold * work.sigma(i))
      flags.push_back(run.first + i);
}

// Least-squares line through (t, p) evaluated at `at`; a single point is held constant.
Eigen::RowVector3d extrapolate(const std::vector<Eigen::Index>& frames, const Trajectory& xyz,
                               Eigen::Index at)
{
  const auto count = static_cast<double>(frames.size());
  double meanT = 0.0;
  Eigen::RowVector3d meanP = Eigen::RowVector3d::Zero();
  for (Eigen::Index f : frames) {
    meanT += static_cast<double>(f);
    meanP += xyz.row(f);
  }
  meanT /= count;
  meanP /= count;
  double stt = 0.0;
  Eigen::RowVector3d stp = Eigen::RowVector3d::Zero();
  for (Eigen::Index f : frames) {
    const double dt = static_cast<double>(f) - meanT;
    stt += dt * dt;
    stp += dt * (xyz.row(f) - meanP);
  }
  if (stt <= 0.0)
    return meanP;
  return meanP + (static_cast<double>(at) - meanT) * (stp / stt);
}

// The replacements of replaceSpikes for one trajectory: `flagged` holds valid frames, ascending
// and unique; appends the replaced frames and their positions. O(#flags · log #flags).
void replaceFlagged(const Trajectory& xyz, const Eigen::Ref<const ValidMask>& valid,
                    const std::vector<Eigen::Index>& flagged, std::vector<Eigen::Index>& frames,
                    std::vector<Eigen::RowVector3d>& positions)
{
  const Eigen::Index frameCount = xyz.rows();
  auto isFlagged = [&](Eigen::Index f) { return std::binary_search(flagged.begin(), flagged.end(), f); };
  auto usable = [&](Eigen::Index f) { return f >= 0 && f < frameCount && valid(f) && !isFlagged(f); };
  std::size_t i = 0;
  while (i < flagged.size()) {
    // A block of consecutive flagged frames [first, last].
    const Eigen::Index first = flagged[i];
    Eigen::Index last = first;
    while (i + 1 < flagged.size() && flagged[i + 1] == last + 1)
      last = flagged[++i];
    ++i;
    const bool left = usable(first - 1);
    const bool right = usable(last + 1);
    std::vector<Eigen::Index> support;
    if (!left && right) {
      for (Eigen::Index f = last + 1; f < frameCount && valid(f) && support.size() < 4; ++f)
        if (!isFlagged(f))
          support.push_back(f);
    } else if (left && !right) {
      for (Eigen::Index f = first - 1; f >= 0 && valid(f) && support.size() < 4; --f)
        if (!isFlagged(f))
          support.push_back(f);
    }
    if (!left && !right)
      continue;  // the block is a whole run: nothing to rebuild it from
    for (Eigen::Index f = first; f <= last; ++f) {
      frames.push_back(f);
      if (left && right) {
        const double u = static_cast<double>(f - first + 1) / static_cast<double>(last - first + 2);
        positions.push_back((1.0 - u) * xyz.row(first - 1) + u * xyz.row(last + 1));  // eq 10 for one sample
      } else {
        positions.push_back(extrapolate(support, xyz, f));
      }
    }
  }
}

// One pass of the detector over every valid run of a trajectory whose samples are checked.
std::vector<Eigen::Index> detectOnce(const Trajectory& xyz, const Eigen::Ref<const ValidMask>& valid,
                                     const SpikeOptions& options, double floor)
{
  std::vector<Eigen::Index> flags;
  RobustWork work;
  for (const Run& run : validRuns(valid)) {
    if (options.method == SpikeMethod::Paper)
      detectPaper(xyz, run, options.factor, flags);
    else
      detectRobust(xyz, run, options.threshold, floor, work, flags);
  }
  return flags;
}

std::vector<Eigen::Index> detectIn(const Trajectory& xyz, const Eigen::Ref<const ValidMask>& valid,
                                   const SpikeOptions& options, double floor)
{
  if (xyz.rows() != valid.size())
    throw InvalidArgument("trajectory has " + std::to_string(xyz.rows()) + " frames but its validity mask " +
                          std::to_string(valid.size()));
  for (Eigen::Index f = 0; f < xyz.rows(); ++f)
    if (valid(f) && !xyz.row(f).allFinite())
      throw InvalidArgument("valid sample at frame " + std::to_string(f) + " is not a finite position");
  std::vector<Eigen::Index> flags = detectOnce(xyz, valid, options, floor);
  if (options.method == SpikeMethod::Paper)
    return flags;  // eq 9 as written: one pass
  // A spike can hide a smaller one beside it (it widens the local scale); once it is replaced,
  // the neighbour stands out. So the detector judges the trajectory again with its flags so far
  // replaced exactly as replaceSpikes will, until a pass adds nothing: repairing the flags and
  // detecting again with the same settings then finds nothing new.
  Eigen::Matrix<double, Eigen::Dynamic, 3> repaired;
  std::vector<Eigen::Index> frames;
  std::vector<Eigen::RowVector3d> positions;
  for (int pass = 1; pass < options.maxPasses && !flags.empty(); ++pass) {
    repaired = xyz;
    frames.clear();
    positions.clear();
    replaceFlagged(xyz, valid, flags, frames, positions);
    for (std::size_t k = 0; k < frames.size(); ++k)
      repaired.row(frames[k]) = positions[k];
    const std::vector<Eigen::Index> again = detectOnce(repaired, valid, options, floor);
    std::vector<Eigen::Index> merged;
    merged.reserve(flags.size() + again.size());
    std::set_union(flags.begin(), flags.end(), again.begin(), again.end(), std::back_inserter(merged));
    if (merged.size() == flags.size())
      break;
    flags = std::move(merged);
  }
  return flags;
}

} // namespace

namespace {

constexpr EnumTable<SpikeMethod, 2> kSpikeMethods{{{
    {SpikeMethod::Paper, "paper"},
    {SpikeMethod::Robust, "robust"},
}}};

} // namespace

std::optional<SpikeMethod> parseSpikeMethod(std::string_view name)
{
  return kSpikeMethods.parse(name);
}

std::string_view spikeMethodName(SpikeMethod method)
{
  return kSpikeMethods.name(method, "robust");
}

std::string spikeMethodNames()
{
  return kSpikeMethods.names();
}

std::vector<Eigen::Index> detectSpikes(const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>& xyz,
                                       const Eigen::Ref<const ValidMask>& valid, const SpikeOptions& options)
{
  checkSpikeOptions(options);
  return detectIn(xyz, valid, options, options.noiseFloor);
}

std::vector<SpikeFlag> detectSpikes(const Take& take, const SpikeOptions& options, const JobControl& job)
{
  checkSpikeOptions(options);
  const double floor = options.noiseFloor / millimetresPer(take.units());
  std::vector<SpikeFlag> flags;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    job.checkpoint(static_cast<double>(m) / static_cast<double>(take.markerCount()));
    if (!isMarker(take, m))
      continue;
    std::vector<Eigen::Index> frames;
    try {
      frames = detectIn(take.trajectory(m), take.valid().col(m), options, floor);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument("marker " + take.label(m) + ": " + e.what());
    }
    for (Eigen::Index f : frames)
      flags.push_back({m, f});
  }
  return flags;
}

std::vector<SamplePatch> replaceSpikes(const Take& take, const std::vector<SpikeFlag>& flags)
{
  for (const SpikeFlag& flag : flags)
    if (flag.marker < 0 || flag.marker >= take.markerCount() || flag.frame < 0 ||
        flag.frame >= take.frameCount())
      throw InvalidArgument("spike flag (marker " + std::to_string(flag.marker) + ", frame " +
                            std::to_string(flag.frame) + ") lies outside the take");
  std::vector<SpikeFlag> sorted;
  sorted.reserve(flags.size());
  for (const SpikeFlag& flag : flags)
    if (take.isValid(flag.frame, flag.marker))
      sorted.push_back(flag);
  std::sort(sorted.begin(), sorted.end(), [](const SpikeFlag& a, const SpikeFlag& b) {
    return a.marker != b.marker ? a.marker < b.marker : a.frame < b.frame;
  });
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());

  std::vector<SamplePatch> patches;
  std::size_t b = 0;
  std::vector<Eigen::Index> flagged;
  while (b < sorted.size()) {
    const Eigen::Index marker = sorted[b].marker;
    flagged.clear();
    for (; b < sorted.size() && sorted[b].marker == marker; ++b)
      flagged.push_back(sorted[b].frame);
    std::vector<Eigen::Index> frames;
    std::vector<Eigen::RowVector3d> positions;
    replaceFlagged(take.trajectory(marker), take.valid().col(marker), flagged, frames, positions);
    if (!frames.empty()) {
      Eigen::Matrix<double, Eigen::Dynamic, 3> matrix(static_cast<Eigen::Index>(positions.size()), 3);
      for (std::size_t r = 0; r < positions.size(); ++r)
        matrix.row(static_cast<Eigen::Index>(r)) = positions[r];
      patches.push_back(makePatch(marker, std::move(frames), std::move(matrix), SampleOrigin::Edited));
    }
  }
  return patches;
}

} // namespace mocap
