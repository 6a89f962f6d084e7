// Smoothing a 60-marker × 10 000-frame take (100 Hz, 0.5 mm noise, a 50-frame gap in every
// marker every 1150 frames) with each method through smoothTake, against the reference of a plain
// 5-point moving average over the same valid runs (the cheapest smoother there is).
// Target (issue 3): B-spline smoothing a small part of the cleaning pipeline's 100 ms.
#include "mocap/base/random.h"
#include "mocap/cleaning/smoothing.h"
#include "mocap/model/valid_runs.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

const mocap::Take& largeTake()
{
  static const mocap::Take take = [] {
    const Eigen::Index markers = 60, frames = 10000;
    std::vector<std::string> labels;
    for (Eigen::Index m = 0; m < markers; ++m)
      labels.push_back("face" + std::to_string(m));
    mocap::Take t(labels, frames, 100.0);
    mocap::Random random(7);
    const auto noise = [&random] { return 0.5 * random.normal(); };
    for (Eigen::Index m = 0; m < markers; ++m) {
      const double phase = static_cast<double>(m);
      for (Eigen::Index f = 0; f < frames; ++f) {
        const double s = static_cast<double>(f) / 100.0;
        t.setPosition(f, m,
                      {20.0 * std::sin(1.3 * s + phase) + noise(),
                       5.0 * phase + 8.0 * std::sin(2.9 * s) + noise(),
                       1000.0 + 10.0 * std::cos(0.7 * s + phase) + noise()});
        const bool occluded = (f / 50 + m) % 23 == 0;
        t.valid()(f, m) = !occluded;
        t.residuals()(f, m) = occluded ? -1.0 : 0.5;
      }
    }
    return t;
  }();
  return take;
}

void BM_MovingAverage5(benchmark::State& state)
{
  const mocap::Take& take = largeTake();
  Eigen::Matrix<double, Eigen::Dynamic, 3> out(take.frameCount(), 3);
  for (auto _ : state) {
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      const auto xyz = take.trajectory(m);
      for (const mocap::ValidRun& run : mocap::findValidRuns(take.valid().col(m))) {
        const Eigen::Index end = run.first + run.length;
        for (Eigen::Index f = run.first; f < end; ++f) {
          const Eigen::Index lo = std::max(run.first, f - 2), hi = std::min(end - 1, f + 2);
          out.row(f) = xyz.middleRows(lo, hi - lo + 1).colwise().mean();
        }
      }
      benchmark::DoNotOptimize(out.data());
    }
  }
}
BENCHMARK(BM_MovingAverage5)->Unit(benchmark::kMillisecond);

void smooth(benchmark::State& state, mocap::SmoothOptions options)
{
  const mocap::Take& take = largeTake();
  std::int64_t samples = 0;
  for (auto _ : state) {
    std::vector<mocap::SamplePatch> patches = mocap::smoothTake(take, options);
    benchmark::DoNotOptimize(patches.data());
    samples += static_cast<std::int64_t>(take.valid().count());
  }
  state.counters["samples/s"] = benchmark::Counter(static_cast<double>(samples), benchmark::Counter::kIsRate);
}

mocap::SmoothOptions with(mocap::SmoothMethod method)
{
  mocap::SmoothOptions o;
  o.method = method;
  return o;
}

void BM_BSplineCubic(benchmark::State& state)
{
  smooth(state, with(mocap::SmoothMethod::BSpline));
}
BENCHMARK(BM_BSplineCubic)->Unit(benchmark::kMillisecond);

void BM_BSplineDegree7(benchmark::State& state)
{
  mocap::SmoothOptions o = with(mocap::SmoothMethod::BSpline);
  o.degree = 7;
  smooth(state, o);
}
BENCHMARK(BM_BSplineDegree7)->Unit(benchmark::kMillisecond);

void BM_Butterworth6Hz(benchmark::State& state)
{
  smooth(state, with(mocap::SmoothMethod::Butterworth));
}
BENCHMARK(BM_Butterworth6Hz)->Unit(benchmark::kMillisecond);

void BM_ButterworthWinter(benchmark::State& state)
{
  mocap::SmoothOptions o = with(mocap::SmoothMethod::Butterworth);
  o.winterCutoff = true;
  smooth(state, o);
}
BENCHMARK(BM_ButterworthWinter)->Unit(benchmark::kMillisecond);

void BM_GcvsplCutoff(benchmark::State& state)
{
  mocap::SmoothOptions o = with(mocap::SmoothMethod::Gcvspl);
  o.gcvsplMode = mocap::SmoothingSplineMode::Cutoff;
  smooth(state, o);
}
BENCHMARK(BM_GcvsplCutoff)->Unit(benchmark::kMillisecond);

void BM_GcvsplGcvCubic(benchmark::State& state)
{
  smooth(state, with(mocap::SmoothMethod::Gcvspl));
}
BENCHMARK(BM_GcvsplGcvCubic)->Unit(benchmark::kMillisecond);

void BM_GcvsplGcvQuintic(benchmark::State& state)
{
  mocap::SmoothOptions o = with(mocap::SmoothMethod::Gcvspl);
  o.gcvsplDegree = 5;
  smooth(state, o);
}
BENCHMARK(BM_GcvsplGcvQuintic)->Unit(benchmark::kMillisecond);

void BM_SavGol(benchmark::State& state)
{
  smooth(state, with(mocap::SmoothMethod::SavGol));
}
BENCHMARK(BM_SavGol)->Unit(benchmark::kMillisecond);

void BM_Default(benchmark::State& state)
{
  smooth(state, mocap::SmoothOptions{});
}
BENCHMARK(BM_Default)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
