// Writing the solved rig as binary FBX: the bundled ICT FaceKit rig (53 shapes,
// resources/sample/ict_face_rig.glb) with 3 000 frames of weights, the size of the sample take's
// solve. Target (issue 32): < 0.5 s for the whole file. Reference in the same run: the same rig
// and weights written as GLB by TinyGLTF (gltf_writer), the other animated-rig export.
#include "mocap/io/fbx_writer.h"
#include "mocap/io/gltf_rig_reader.h"
#include "mocap/io/gltf_writer.h"
#include "checkout_paths.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

namespace {

constexpr Eigen::Index kFrames = 3000;

struct Solve
{
  mocap::BlendshapeRig rig;
  Eigen::MatrixXd weights;
};

// Weights as smooth sines in [0, 1], one phase per shape.
const Solve& sampleSolve()
{
  static const Solve solve = [] {
    Solve s;
    s.rig = mocap::readGltfRig(std::filesystem::path(mocap::checkout::sourceDir()) / "resources/sample/ict_face_rig.glb");
    s.weights.resize(kFrames, s.rig.shapeCount());
    for (Eigen::Index f = 0; f < kFrames; ++f)
      for (Eigen::Index c = 0; c < s.rig.shapeCount(); ++c)
        s.weights(f, c) = 0.5 + 0.5 * std::sin(0.01 * static_cast<double>(f) + static_cast<double>(c));
    return s;
  }();
  return solve;
}

void BM_RigFbx(benchmark::State& state)
{
  const Solve& s = sampleSolve();
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string file = mocap::rigFbx(s.rig, s.weights, 100.0, {});
    bytes = file.size();
    benchmark::DoNotOptimize(file.data());
  }
  state.counters["shapes"] = static_cast<double>(s.rig.shapeCount());
  state.counters["frames"] = static_cast<double>(kFrames);
  state.counters["MB"] = static_cast<double>(bytes) / 1e6;
}
BENCHMARK(BM_RigFbx)->Unit(benchmark::kMillisecond);

void BM_RigGlbReference(benchmark::State& state)
{
  const Solve& s = sampleSolve();
  for (auto _ : state) {
    const std::string file = mocap::rigGlb(s.rig, s.weights, 100.0);
    benchmark::DoNotOptimize(file.data());
  }
}
BENCHMARK(BM_RigGlbReference)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
