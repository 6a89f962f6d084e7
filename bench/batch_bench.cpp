// `mocap batch` throughput (issue 17): the test takes cleaned with --jobs 1 (the reference, in the
// same run) and --jobs 2, in takes/s and MB/s read; and a synthetic archive of 100 and of 1 000
// takes cleaned end to end, with the wall time and the peak resident memory after each, so the
// two show whether memory grows with the number of takes (it must not: one take per job lives at
// a time, and only a few numbers per take are kept).
// Measured here (2 cores shared with other builds, load 2–3): the 22 test takes 22.3 takes/s
// (5.0 MB/s) with 1 job, 29.4 takes/s (6.6 MB/s) with 2, 1.32× (each take's files are fsync'd:
// about a third of the one-job wall time is waiting for the disk); the synthetic archive: 100 takes
// 5.0 s, peak 9.8 MB; 1 000 takes 36.8 s (27 takes/s), peak 10.8 MB.
#include "mocap/base/file_io.h"
#include "mocap/base/random.h"
#include "mocap/batch/batch_runner.h"
#include "mocap/io/take_io.h"
#include "checkout_paths.h"

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <cmath>
#include <filesystem>
#include <random>

namespace {

namespace fs = std::filesystem;

/// A fresh folder for one benchmark, removed afterwards.
struct ScratchDir
{
  ScratchDir()
  {
    std::random_device random;
    path = fs::temp_directory_path() / ("mocap-batch-bench-" + std::to_string(random()));
    fs::create_directories(path);
  }
  ~ScratchDir()
  {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  fs::path path;
};

double peakResidentMegabytes()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

/// The bundled test takes (C3D of several layouts and sizes), as one manifest.
fs::path testTakesManifest(const fs::path& folder)
{
  std::string manifest;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(mocap::checkout::testDataDir()) / "c3d"))
    if (entry.is_regular_file() && mocap::lowerExtension(entry.path()) == "c3d" &&
        entry.path().string().find("sample18") == std::string::npos)  // the corrupt one
      manifest += entry.path().string() + "\n";
  const fs::path path = folder / "takes.txt";
  mocap::writeFileAtomically(path, manifest);
  return path;
}

void runAndCount(benchmark::State& state, const mocap::TakeManifest& manifest, const fs::path& outDir, int jobs)
{
  mocap::BatchOptions options;
  options.outDir = outDir;
  options.jobs = jobs;
  std::int64_t takes = 0, bytes = 0;
  for (auto _ : state) {
    const mocap::BatchResult result = mocap::runBatch(manifest, options);
    if (result.count(mocap::TakeStatus::Failed) > 0)
      state.SkipWithError("a take failed");
    takes += static_cast<std::int64_t>(result.takes.size());
    bytes += result.inputBytes;
  }
  state.counters["takes_per_s"] = benchmark::Counter(static_cast<double>(takes), benchmark::Counter::kIsRate);
  state.counters["MB_per_s"] = benchmark::Counter(static_cast<double>(bytes) / 1e6, benchmark::Counter::kIsRate);
}

void BM_BatchTestTakes(benchmark::State& state)
{
  ScratchDir scratch;
  const mocap::TakeManifest manifest = mocap::readManifest(testTakesManifest(scratch.path));
  state.counters["takes"] = static_cast<double>(manifest.takes.size());
  runAndCount(state, manifest, scratch.path / "out", static_cast<int>(state.range(0)));
}

/// A small synthetic take: 30 markers × 600 frames at 100 Hz, smooth motion with noise, a few gaps.
mocap::Take syntheticTake(std::uint64_t seed)
{
  const Eigen::Index markers = 30, frames = 600;
  std::vector<std::string> labels;
  for (Eigen::Index m = 0; m < markers; ++m)
    labels.push_back("m" + std::to_string(m));
  mocap::Take take(labels, frames, 100.0);
  mocap::Random random(seed);
  for (Eigen::Index m = 0; m < markers; ++m)
    for (Eigen::Index f = 0; f < frames; ++f) {
      const double t = static_cast<double>(f) / 100.0, phase = 0.2 * static_cast<double>(m);
      take.setPosition(f, m,
                       {10.0 * static_cast<double>(m) + 5.0 * std::sin(t + phase) + 0.05 * random.normal(),
                        3.0 * std::cos(2.0 * t + phase) + 0.05 * random.normal(), 1000.0 + 0.05 * random.normal()});
      take.valid()(f, m) = true;
      take.residuals()(f, m) = 0.0;
    }
  for (int g = 0; g < 10; ++g) {
    const Eigen::Index m = random.below(markers), n = 3 + random.below(Eigen::Index{40});
    take.valid().col(m).segment(1 + random.below(frames - n - 2), n).setConstant(false);
  }
  return take;
}

/// `count` synthetic takes in ten session folders, written once per process.
mocap::TakeManifest syntheticArchive(const fs::path& folder, std::size_t count)
{
  for (std::size_t i = 0; i < count; ++i) {
    const fs::path path = folder / ("session" + std::to_string(i % 10)) / ("take" + std::to_string(i) + ".c3d");
    fs::create_directories(path.parent_path());
    mocap::writeTake(syntheticTake(i + 1), path);
  }
  return mocap::readManifest(folder);
}

void BM_SyntheticArchive(benchmark::State& state)
{
  ScratchDir scratch;
  const auto count = static_cast<std::size_t>(state.range(0));
  const mocap::TakeManifest manifest = syntheticArchive(scratch.path / "archive", count);
  runAndCount(state, manifest, scratch.path / "out", 0);
  state.counters["peak_rss_MB"] = peakResidentMegabytes();
}
// 100 first, then 1 000: the peak after the larger archive shows any growth with takes.
BENCHMARK(BM_SyntheticArchive)->ArgName("takes")->Arg(100)->Arg(1000)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);
// After the synthetic archives, so their peak memory is theirs alone.
BENCHMARK(BM_BatchTestTakes)->ArgName("jobs")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

} // namespace

BENCHMARK_MAIN();
