// Stage 1 of the robust spike detector: the median line (spike_detection.h, step 1).

#include "spike_detector_parts.h"
#include "spike_lanes.h"
#include "median_networks.h"
#if defined(MOCAP_AVX2_KERNELS)
#include "spike_kernels_avx2.h"
#endif

#include <array>
#include <cstdlib>

namespace mocap::spikes {

namespace {

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

} // namespace

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

} // namespace mocap::spikes
