// Stage 2 of the robust spike detector: each sample predicted by a tricube-weighted local
// quadratic without itself and its worst suspects (spike_detection.h, step 2).

#include "spike_detector_parts.h"
#include "spike_lanes.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace mocap::spikes {

namespace {

// Tricube-weighted quadratic fits over a window of 9 samples that leave out the sample at `centre`
// (window index 0..8; off the middle only near a run end). The sums and the prediction filter
// without suspects depend on nothing but the centre, so they are computed once.
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

} // namespace

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

} // namespace mocap::spikes
