// Spike detection on a synthetic facial take (60 markers × 10 000 frames at 100 Hz: a few mm of
// smooth expression motion per marker, 0.1 mm noise, occasional occlusions and 1 % spikes),
// against the reference of one plain pass computing every consecutive displacement length (what
// eq 8 needs, so the paper detector's floor). Both detectors are O(#frames · #markers).
// Measured (RelWithDebInfo, 2 shared cores, CPU time): reference 1.2-1.5 ms, paper 3.1-4.6 ms
// (~3×), robust 55 ms at first (three small median networks, a 9-sample fit and two 11-sample
// medians per sample, two neighbouring samples per vector register; 106-108 ms one sample at a
// time), 27-28 ms after the filter table, the rolling scale and the shared middle pairs, and
// 22 ms with stage 1 on four lanes where the CPU has AVX2 (MOCAP_NO_AVX2=1 measures the two-lane
// path); replaceSpikes 0.4 ms for ~6 000 flags.
#include "mocap/base/random.h"
#include "mocap/cleaning/spike_detection.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

const mocap::Take& facialTake()
{
  static const mocap::Take take = [] {
    const Eigen::Index markers = 60, frames = 10000;
    std::vector<std::string> labels;
    for (Eigen::Index m = 0; m < markers; ++m)
      labels.push_back("face" + std::to_string(m));
    mocap::Take t(labels, frames, 100.0);
    mocap::Random random(11);
    const auto noise = [&random] { return 0.1 * random.normal(); };
    for (Eigen::Index m = 0; m < markers; ++m) {
      const double phase = static_cast<double>(m);
      for (Eigen::Index f = 0; f < frames; ++f) {
        const double s = static_cast<double>(f) / 100.0;
        // Head sway plus expression bursts (jaw, brows) of a few millimetres.
        const Eigen::Vector3d p(40.0 * std::sin(0.3 * s) + 3.0 * std::sin(2.1 * s + phase) + noise(),
                                -250.0 + 5.0 * std::sin(1.3 * s + 0.5 * phase) * std::sin(0.7 * s) +
                                    noise(),
                                1000.0 + 2.0 * std::cos(3.7 * s + phase) + noise());
        const bool occluded = (f / 40 + m) % 31 == 0;
        t.setPosition(f, m, occluded ? Eigen::Vector3d::Zero() : p);
        t.valid()(f, m) = !occluded;
        t.residuals()(f, m) = occluded ? -1.0 : 0.0;
        if (!occluded && random.uniform() < 0.01)
          t.setPosition(f, m, p + Eigen::Vector3d(3.0, -3.0, 2.0));
      }
    }
    return t;
  }();
  return take;
}

void BM_DisplacementLengths(benchmark::State& state)
{
  const mocap::Take& take = facialTake();
  for (auto _ : state) {
    double total = 0.0;
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      const auto xyz = take.trajectory(m);
      const auto valid = take.valid().col(m);
      for (Eigen::Index f = 1; f < take.frameCount(); ++f)
        if (valid(f) && valid(f - 1))
          total += (xyz.row(f) - xyz.row(f - 1)).norm();
    }
    benchmark::DoNotOptimize(total);
  }
  state.SetItemsProcessed(state.iterations() * take.frameCount() * take.markerCount());
}
BENCHMARK(BM_DisplacementLengths)->Unit(benchmark::kMillisecond);

void detect(benchmark::State& state, mocap::SpikeMethod method)
{
  const mocap::Take& take = facialTake();
  mocap::SpikeOptions options;
  options.method = method;
  std::size_t flagged = 0;
  for (auto _ : state) {
    const auto flags = mocap::detectSpikes(take, options);
    flagged = flags.size();
    benchmark::DoNotOptimize(flags.data());
  }
  state.counters["flagged"] = static_cast<double>(flagged);
  state.SetItemsProcessed(state.iterations() * take.frameCount() * take.markerCount());
}

void BM_DetectPaper(benchmark::State& state)
{
  detect(state, mocap::SpikeMethod::Paper);
}
BENCHMARK(BM_DetectPaper)->Unit(benchmark::kMillisecond);

void BM_DetectRobust(benchmark::State& state)
{
  detect(state, mocap::SpikeMethod::Robust);
}
BENCHMARK(BM_DetectRobust)->Unit(benchmark::kMillisecond);

void BM_ReplaceSpikes(benchmark::State& state)
{
  const mocap::Take& take = facialTake();
  const auto flags = mocap::detectSpikes(take, {});
  for (auto _ : state) {
    const auto patches = mocap::replaceSpikes(take, flags);
    benchmark::DoNotOptimize(patches.data());
  }
}
BENCHMARK(BM_ReplaceSpikes)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
