// Reading a large float C3D (60 markers × 20 000 frames, ~19 MB, written by our own writer)
// against the reference of reading the same file's bytes from the disk cache.
// Target (issue 2): readC3d within 3× of BM_ReadFileBytes.
#include "mocap/base/random.h"
#include "mocap/io/c3d_reader.h"
#include "mocap/io/c3d_writer.h"
#include "mocap/base/file_io.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

namespace {

const std::filesystem::path& largeTake()
{
  static const std::filesystem::path path = [] {
    const Eigen::Index markers = 60, frames = 20000;
    std::vector<std::string> labels;
    for (Eigen::Index m = 0; m < markers; ++m)
      labels.push_back("face" + std::to_string(m));
    mocap::Take take(labels, frames, 120.0);
    mocap::Random random(7);
    for (Eigen::Index m = 0; m < markers; ++m)
      for (Eigen::Index f = 0; f < frames; ++f) {
        const double t = static_cast<double>(f) / 120.0;
        take.setPosition(f, m, {100.0 * std::sin(t + static_cast<double>(m)) + (0.4 * random.uniform() - 0.2), 5.0 * static_cast<double>(m),
                                1000.0 + 10.0 * std::cos(t)});
        const bool occluded = (f / 50 + m) % 23 == 0;
        take.valid()(f, m) = !occluded;
        take.residuals()(f, m) = occluded ? -1.0 : 0.0;
      }
    const auto file = std::filesystem::temp_directory_path() / "mocap_bench_large.c3d";
    mocap::writeC3d(take, file);
    return file;
  }();
  return path;
}

void BM_ReadFileBytes(benchmark::State& state)
{
  const auto& path = largeTake();
  for (auto _ : state) {
    std::string bytes = mocap::readFileBytes(path);
    benchmark::DoNotOptimize(bytes.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(std::filesystem::file_size(path)));
}
BENCHMARK(BM_ReadFileBytes)->Unit(benchmark::kMillisecond);

void BM_ReadC3d(benchmark::State& state)
{
  const auto& path = largeTake();
  for (auto _ : state) {
    mocap::Take take = mocap::readC3d(path);
    benchmark::DoNotOptimize(take.positionData());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(std::filesystem::file_size(path)));
}
BENCHMARK(BM_ReadC3d)->Unit(benchmark::kMillisecond);

void BM_EncodeC3d(benchmark::State& state)
{
  const mocap::Take take = mocap::readC3d(largeTake());
  for (auto _ : state) {
    std::string bytes = mocap::encodeC3d(take);
    benchmark::DoNotOptimize(bytes.data());
  }
}
BENCHMARK(BM_EncodeC3d)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
