// The cleaning pipeline of issue 3 on 60 markers × 10 000 frames: robust spike detection and
// replacement, `auto` gap filling and B-spline smoothing, one core. Target: < 100 ms, linear in
// frames (compare the 5 000 and 10 000 frame runs). Reference in the same run: one pass that
// copies every trajectory (the cost of touching the data at all).
#include "mocap/base/random.h"
#include "mocap/cleaning/clean_pipeline.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

/// Facial-like motion: markers on a moving "head" with local smooth deformation, noise,
/// ~3 % of samples in gaps of 5–120 frames, and a few spikes.
mocap::Take syntheticTake(Eigen::Index frames)
{
  const Eigen::Index markers = 60;
  std::vector<std::string> labels;
  for (Eigen::Index m = 0; m < markers; ++m)
    labels.push_back("m" + std::to_string(m));
  mocap::Take take(labels, frames, 120.0);
  mocap::Random random(11);
  const auto noise = [&random] { return 0.05 * random.normal(); };
  for (Eigen::Index m = 0; m < markers; ++m) {
    const double u = static_cast<double>(m % 10) * 15.0, v = static_cast<double>(m / 10) * 20.0;
    for (Eigen::Index f = 0; f < frames; ++f) {
      const double t = static_cast<double>(f) / 120.0;
      const double yaw = 0.2 * std::sin(0.3 * t);
      const double local = 3.0 * std::sin(2.0 * t + 0.1 * static_cast<double>(m));
      const double x = u * std::cos(yaw) + 10.0 * std::sin(0.5 * t);
      const double y = u * std::sin(yaw) + local;
      take.setPosition(f, m, {x + noise(), y + noise(), 1000.0 + v + local + noise()});
      take.valid()(f, m) = true;
      take.residuals()(f, m) = 0.0;
    }
  }
  const Eigen::Index hidden = frames * markers * 3 / 100;
  for (Eigen::Index total = 0; total < hidden;) {
    const Eigen::Index m = random.below(markers), n = 5 + random.below(Eigen::Index{116});
    const Eigen::Index start = 1 + random.below(frames - n - 2);
    take.valid().col(m).segment(start, n).setConstant(false);
    total += n;
  }
  for (int s = 0; s < 200; ++s) {
    const Eigen::Index m = random.below(markers), f = random.below(frames);
    if (take.isValid(f, m))
      take.setPosition(f, m, take.position(f, m) + Eigen::Vector3d(5.0, 0.0, 0.0));
  }
  return take;
}

void BM_CleanPipeline(benchmark::State& state)
{
  const mocap::Take original = syntheticTake(state.range(0));
  mocap::CleanOptions options;  // robust spikes, auto fill, default smoothing
  options.smooth = mocap::SmoothOptions{};
  options.smooth->method = mocap::SmoothMethod::BSpline;
  for (auto _ : state) {
    state.PauseTiming();
    mocap::Take take = original;
    state.ResumeTiming();
    const mocap::CleanReport report = mocap::cleanTake(take, options);
    benchmark::DoNotOptimize(report.filledSamples);
  }
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_CleanPipeline)->Arg(5000)->Arg(10000)->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);

// One step of the pipeline alone (0 spikes, 1 fill, 2 smoothing), on the take as the step
// before it leaves it, to show where the pipeline's time goes.
void BM_CleanStep(benchmark::State& state)
{
  const int step = static_cast<int>(state.range(1));
  mocap::CleanOptions before;
  before.smooth.reset();
  if (step < 1)
    before.spikes.reset();
  if (step < 2)
    before.fill.reset();
  mocap::Take original = syntheticTake(state.range(0));
  mocap::cleanTake(original, before);
  mocap::CleanOptions only;
  only.spikes.reset();
  only.fill.reset();
  only.smooth.reset();
  if (step == 0)
    only.spikes = mocap::SpikeOptions{};
  else if (step == 1)
    only.fill = mocap::FillOptions{};
  else
    only.smooth = mocap::SmoothOptions{mocap::SmoothMethod::BSpline};
  for (auto _ : state) {
    state.PauseTiming();
    mocap::Take take = original;
    state.ResumeTiming();
    const mocap::CleanReport report = mocap::cleanTake(take, only);
    benchmark::DoNotOptimize(report.filledSamples);
  }
}
BENCHMARK(BM_CleanStep)->ArgNames({"frames", "step"})->Args({10000, 0})->Args({10000, 1})->Args({10000, 2})
    ->Unit(benchmark::kMillisecond);

void BM_TouchEverySample(benchmark::State& state)
{
  const mocap::Take original = syntheticTake(state.range(0));
  for (auto _ : state) {
    double sum = 0.0;
    for (Eigen::Index m = 0; m < original.markerCount(); ++m)
      sum += original.trajectory(m).sum();
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_TouchEverySample)->Arg(10000)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
