// Marker layout planning on the 41-marker AnimFace take (tests/data/trc/NoseMoCap.trc): the PFA
// sweep of the issue (1000 k-means restarts for every useful k) on all cores against the same
// sweep on one thread (the reference), and the whole plan (sweep + greedy + random baselines +
// both errors at every size). Target: the multi-threaded sweep under 10 s on a 2-core machine.
// A wall-clock line for each is printed before the benchmark table.
#include "mocap/layout/layout_frames.h"
#include "mocap/layout/layout_planning.h"
#include "mocap/layout/marker_selection.h"
#include "mocap/io/take_io.h"
#include "checkout_paths.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <thread>

namespace {

struct Input
{
  mocap::LayoutFrames frames;
  mocap::MarkerSymmetry symmetry;
};

const Input& input()
{
  static const Input data = [] {
    const std::vector<mocap::Take> takes{
        mocap::readTake(std::string(mocap::checkout::testDataDir()) + "/trc/NoseMoCap.trc")};
    Input result{mocap::collectLayoutFrames(takes, {}), mocap::MarkerSymmetry()};
    const Eigen::Index neutral = mocap::findNeutralFrame(result.frames.frames, result.frames.training);
    Eigen::MatrixX3d positions(result.frames.markerCount(), 3);
    for (Eigen::Index m = 0; m < result.frames.markerCount(); ++m)
      positions.row(m) = result.frames.frames.row(neutral).segment<3>(3 * m);
    result.symmetry = mocap::detectMarkerPairs(positions, result.frames.labels).symmetry;
    return result;
  }();
  return data;
}

mocap::PfaSweep sweep(int threads)
{
  const Input& data = input();
  return mocap::sweepPfa(data.frames.frames(data.frames.training, Eigen::all), data.symmetry, {},
                         mocap::JobControl().withThreads(threads));
}

void BM_PfaSweep(benchmark::State& state)
{
  const int threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const mocap::PfaSweep result = sweep(threads);
    benchmark::DoNotOptimize(result.selections.data());
    state.counters["k"] = static_cast<double>(result.selections.size());
  }
}
// Arg 1: the single-threaded reference; arg 0: every hardware thread.
BENCHMARK(BM_PfaSweep)->Arg(1)->Arg(0)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(2);

void BM_PlanMarkerLayout(benchmark::State& state)
{
  const Input& data = input();
  for (auto _ : state) {
    const mocap::LayoutPlan plan = mocap::planMarkerLayout(data.frames, data.symmetry);
    benchmark::DoNotOptimize(plan.sizes.data());
  }
}
BENCHMARK(BM_PlanMarkerLayout)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

void printWallClock()
{
  const auto time = [](const auto& run) {
    const auto start = std::chrono::steady_clock::now();
    run();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  (void)input();
  const double one = time([] { (void)sweep(1); });
  const double all = time([] { (void)sweep(0); });
  const double plan = time([] { (void)mocap::planMarkerLayout(input().frames, input().symmetry); });
  std::printf("wall clock, NoseMoCap 41 markers, 1000 restarts, every useful k: sweep %.2f s on %u threads "
              "(1 thread: %.2f s, speed-up %.2f); whole plan %.2f s; target sweep < 10 s\n",
              all, std::thread::hardware_concurrency(), one, one / all, plan);
}

} // namespace

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  printWallClock();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
