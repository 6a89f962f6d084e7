// Face mesh deformation, per frame and set-up, on the 468-vertex MediaPipe face (tests/data) and
// the 26 719-vertex ICT FaceKit mesh (../shared/data/face_mesh, skipped when absent), both with 40
// controls spread over the face by farthest-point sampling. Targets (issue 5), ICT mesh with ~40
// controls: RBF ≥ 1 000 frames/s and Laplacian ≥ 200 frames/s after set-up, set-up < 2 s.
// References in the same run: the naive RBF (solve eq 2 for the frame, sum eq 3 at every vertex)
// against the precomputed vertex × control product, and the per-frame Cholesky back-substitution
// against the precomputed Laplacian response. The rotation-aware Laplacian (2 iterations) is
// timed too; it has no frame-rate target.
#include "mocap/deform/laplacian_deformer.h"
#include "mocap/io/obj_io.h"
#include "mocap/deform/rbf_deformer.h"
#include "checkout_paths.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <limits>
#include <map>
#include <memory>

namespace {

constexpr Eigen::Index kControls = 40;

struct Fixture
{
  mocap::Mesh mesh;
  std::vector<mocap::Triangle> triangles;
  std::vector<mocap::MeshPoint> controls;
  mocap::PointSet restControls;
  mocap::PointSet displacements;
};

// Mesh 0: MediaPipe; mesh 1: ICT FaceKit (nullptr when the shared data is absent).
const Fixture* fixture(int which)
{
  static std::map<int, std::unique_ptr<Fixture>> cache;
  if (auto found = cache.find(which); found != cache.end())
    return found->second.get();
  const std::filesystem::path path =
      which == 0 ? std::filesystem::path(mocap::checkout::testDataDir()) / "face_mesh/canonical_face_model.obj"
                 : std::filesystem::path(mocap::checkout::sharedDataDir()) / "face_mesh/ict_facekit/generic_neutral_mesh.obj";
  if (!std::filesystem::exists(path))
    return cache.emplace(which, nullptr).first->second.get();
  auto f = std::make_unique<Fixture>();
  f->mesh = mocap::readObj(path);
  f->triangles = f->mesh.triangles();
  // Controls on the face area only (ICT FaceKit: vertices 0…6705, its "narrow face area").
  const Eigen::Index usable = which == 0 ? f->mesh.vertexCount() : std::min<Eigen::Index>(6706, f->mesh.vertexCount());
  Eigen::VectorXd distance = Eigen::VectorXd::Constant(usable, std::numeric_limits<double>::infinity());
  Eigen::Index next = 0;
  for (Eigen::Index c = 0; c < kControls; ++c) {
    f->controls.push_back(mocap::MeshPoint::atVertex(next));
    distance = distance.cwiseMin(
        (f->mesh.vertices.topRows(usable).rowwise() - f->mesh.vertices.row(next)).rowwise().norm());
    distance.maxCoeff(&next);
  }
  f->restControls.resize(kControls, 3);
  for (Eigen::Index c = 0; c < kControls; ++c)
    f->restControls.row(c) = f->mesh.vertices.row(f->controls[static_cast<std::size_t>(c)].vertices[0]);
  f->displacements = mocap::PointSet::Random(kControls, 3) * (0.02 * f->mesh.size());
  return cache.emplace(which, std::move(f)).first->second.get();
}

const Fixture* needFixture(benchmark::State& state)
{
  const Fixture* f = fixture(static_cast<int>(state.range(0)));
  if (!f)
    state.SkipWithError("ICT FaceKit mesh not found under ../shared/data/face_mesh");
  else
    state.SetLabel(std::to_string(f->mesh.vertexCount()) + " vertices, " + std::to_string(kControls) + " controls");
  return f;
}

// Times `step(out)` per iteration and reports frames per second.
template <typename Step>
void frames(benchmark::State& state, const Step& step)
{
  mocap::MeshVertices out;
  for (auto _ : state) {
    step(out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["frames_per_second"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                           benchmark::Counter::kIsRate);
}

mocap::LaplacianOptions laplacianOptions(benchmark::State& state)
{
  mocap::LaplacianOptions options;
  options.weights = static_cast<mocap::LaplacianWeights>(state.range(1));
  return options;
}

std::unique_ptr<mocap::RbfDeformer> rbf(const Fixture& f)
{
  return std::make_unique<mocap::RbfDeformer>(f.mesh.vertices, f.restControls);
}

std::unique_ptr<mocap::LaplacianDeformer> laplacian(const Fixture& f, benchmark::State& state)
{
  return std::make_unique<mocap::LaplacianDeformer>(f.mesh.vertices, f.triangles, f.controls, laplacianOptions(state));
}

void BM_RbfSetup(benchmark::State& state)
{
  if (const Fixture* f = needFixture(state))
    for (auto _ : state)
      benchmark::DoNotOptimize(rbf(*f)->response().data());
}

void BM_RbfFrame(benchmark::State& state)
{
  if (const Fixture* f = needFixture(state)) {
    const auto deformer = rbf(*f);
    frames(state, [&](mocap::MeshVertices& out) { deformer->deform(f->displacements, out); });
  }
}

void BM_RbfFrameNaiveReference(benchmark::State& state)
{
  if (const Fixture* f = needFixture(state)) {
    const auto deformer = rbf(*f);
    frames(state, [&](mocap::MeshVertices& out) { deformer->deformDirect(f->displacements, out); });
  }
}

void BM_LaplacianSetup(benchmark::State& state)
{
  if (const Fixture* f = needFixture(state))
    for (auto _ : state)
      benchmark::DoNotOptimize(laplacian(*f, state)->response().data());
}

void BM_LaplacianFrame(benchmark::State& state)
{
  if (const Fixture* f = needFixture(state)) {
    const auto deformer = laplacian(*f, state);
    frames(state, [&](mocap::MeshVertices& out) { deformer->deform(f->displacements, out); });
  }
}

void BM_LaplacianFrameSubstitutionReference(benchmark::State& state)
{
  if (const Fixture* f = needFixture(state)) {
    const auto deformer = laplacian(*f, state);
    frames(state, [&](mocap::MeshVertices& out) { deformer->deformBySubstitution(f->displacements, out); });
  }
}

void BM_LaplacianFrameRotationAware(benchmark::State& state)
{
  if (const Fixture* f = needFixture(state)) {
    const auto deformer = laplacian(*f, state);
    const std::vector<bool> all(static_cast<std::size_t>(kControls), true);
    frames(state, [&](mocap::MeshVertices& out) {
      deformer->deformRotationAware(f->displacements, all, static_cast<int>(state.range(2)), out);
    });
  }
}

// Arg 0: mesh (0 MediaPipe, 1 ICT); arg 1 (Laplacian): weights (0 uniform, 1 cotangent, 2 mean-value).
BENCHMARK(BM_RbfSetup)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RbfFrame)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RbfFrameNaiveReference)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LaplacianSetup)->Args({0, 2})->Args({1, 0})->Args({1, 1})->Args({1, 2})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LaplacianFrame)->Args({0, 2})->Args({1, 2})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LaplacianFrameSubstitutionReference)->Args({0, 2})->Args({1, 2})->Unit(benchmark::kMicrosecond);
// Arg 2: rotation-aware iterations.
BENCHMARK(BM_LaplacianFrameRotationAware)->Args({0, 2, 2})->Args({1, 2, 2})->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
