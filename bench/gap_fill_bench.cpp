// Gap filling on a long synthetic facial take: 60 markers × 10 000 frames at 100 Hz (head motion,
// six expression modes, 0.1 mm noise) with 3 % of the samples missing in gaps of 5-120 frames.
// `auto` against the reference `linear` in the same run. Target (issue 3): the whole cleaning
// pipeline (spikes + auto fill + smoothing) under 100 ms on one core, so auto fill well under 70 ms,
// and linear in the number of frames (compare the 5 000- and 10 000-frame runs).
#include "mocap/base/random.h"
#include "mocap/cleaning/fill/gap_fill.h"

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include <cmath>

namespace {

mocap::Take syntheticTake(Eigen::Index frames)
{
  const Eigen::Index markers = 60;
  const double rate = 100.0;
  mocap::Random random(11);
  std::vector<std::string> labels;
  for (Eigen::Index m = 0; m < markers; ++m)
    labels.push_back("face" + std::to_string(m));
  mocap::Take take(labels, frames, rate);

  // Rest shape: a patch of an ellipsoid, roughly a face (mm).
  Eigen::Matrix3Xd rest(3, markers);
  for (Eigen::Index m = 0; m < markers; ++m) {
    const double u = -1.0 + 2.0 * random.uniform();
    const double v = -1.0 + 2.0 * random.uniform();
    rest.col(m) =
        Eigen::Vector3d(70.0 * u, 90.0 * v, 60.0 * std::sqrt(std::max(0.0, 1.0 - 0.5 * u * u - 0.3 * v * v)));
  }
  // Six expression modes: smooth displacement fields driven by smooth random signals.
  constexpr int kModes = 6;
  std::vector<Eigen::Matrix3Xd> modes(kModes, Eigen::Matrix3Xd(3, markers));
  std::vector<Eigen::Vector3d> centres(kModes);
  for (int k = 0; k < kModes; ++k) {
    centres[static_cast<std::size_t>(k)] = rest.col(random.below(markers));
    const Eigen::Vector3d direction =
        Eigen::Vector3d(random.normal(), random.normal(), random.normal()).normalized();
    for (Eigen::Index m = 0; m < markers; ++m) {
      const double d = (rest.col(m) - centres[static_cast<std::size_t>(k)]).norm();
      modes[static_cast<std::size_t>(k)].col(m) = 4.0 * std::exp(-d * d / (2.0 * 35.0 * 35.0)) * direction;
    }
  }
  std::vector<double> phase(2 * kModes + 6);
  for (auto& p : phase)
    p = 6.283 * random.uniform();
  for (Eigen::Index f = 0; f < frames; ++f) {
    const double t = static_cast<double>(f) / rate;
    const Eigen::Matrix3d head =
        (Eigen::AngleAxisd(0.08 * std::sin(0.3 * t + phase[0]), Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(0.05 * std::sin(0.5 * t + phase[1]), Eigen::Vector3d::UnitX()))
            .toRotationMatrix();
    const Eigen::Vector3d shift(10.0 * std::sin(0.2 * t + phase[2]), 5.0 * std::sin(0.35 * t + phase[3]),
                                1000.0);
    Eigen::Matrix3Xd shape = rest;
    for (int k = 0; k < kModes; ++k) {
      const double a = std::sin((0.7 + 0.3 * k) * t + phase[static_cast<std::size_t>(6 + k)]) *
                       std::sin(0.13 * (k + 1) * t + phase[static_cast<std::size_t>(6 + kModes + k)]);
      shape += a * modes[static_cast<std::size_t>(k)];
    }
    for (Eigen::Index m = 0; m < markers; ++m) {
      const Eigen::Vector3d noise(random.normal(), random.normal(), random.normal());
      take.setPosition(f, m, head * shape.col(m) + shift + 0.1 * noise);
      take.valid()(f, m) = true;
      take.residuals()(f, m) = 0.5;
    }
  }
  // 3 % of the samples in gaps of 5-120 frames at random places.
  const auto target = static_cast<Eigen::Index>(0.03 * static_cast<double>(frames * markers));
  Eigen::Index hidden = 0;
  while (hidden < target) {
    const Eigen::Index m = random.below(markers);
    const Eigen::Index length = 5 + random.below(Eigen::Index{116});
    const Eigen::Index start =
        1 + random.below(frames - length - 2);
    for (Eigen::Index f = start; f < start + length; ++f)
      if (take.valid()(f, m)) {
        take.valid()(f, m) = false;
        take.residuals()(f, m) = -1.0;
        ++hidden;
      }
  }
  return take;
}

void fill(benchmark::State& state, mocap::FillMethod method)
{
  const mocap::Take take = syntheticTake(state.range(0));
  mocap::FillOptions options{method, 0, 6};
  options.maxGapSeconds = 0.0;  // every gap, as before the defaults that leave some open
  options.extrapolate = true;
  options.minValidFraction = 0.0;
  std::size_t filled = 0;
  for (auto _ : state) {
    const mocap::FillResult result = mocap::fillGaps(take, options);
    filled = result.patches.size();
    benchmark::DoNotOptimize(result.patches.data());
  }
  state.counters["gaps"] = static_cast<double>(filled);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}

void BM_FillLinear(benchmark::State& state)
{
  fill(state, mocap::FillMethod::Linear);
}
void BM_FillAuto(benchmark::State& state)
{
  fill(state, mocap::FillMethod::Auto);
}

BENCHMARK(BM_FillLinear)->Arg(5000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FillAuto)->Arg(5000)->Arg(10000)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
