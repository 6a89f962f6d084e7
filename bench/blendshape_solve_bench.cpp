// Blendshape solve on the ICT FaceKit rig (../shared/data/face_mesh, skipped when absent): its 53
// "expressions" shapes, 40 markers on the face region, a 2 000-frame synthetic take at 100 Hz
// (known smooth weights, 0.5 mm noise). Targets (issue 15, one core): bvls and ridge ≥ 20 000
// frames/s, temporal ≥ 5 000 frames/s, rig set-up < 1 s. Reference in the same run: a naive
// per-frame dense solve that forms and factorises the normal equations anew for every frame.
#include "mocap/base/file_io.h"
#include "mocap/base/json_reader.h"
#include "mocap/base/random.h"
#include "mocap/deform/blendshape_solver.h"
#include "mocap/io/obj_rig_reader.h"
#include "mocap/math/bounded_least_squares.h"
#include "checkout_paths.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <memory>

namespace {

constexpr Eigen::Index kMarkers = 40, kFrames = 2000;
const std::filesystem::path kIct = std::filesystem::path(mocap::checkout::sharedDataDir()) / "face_mesh/ict_facekit";

std::vector<std::string> expressionNames()
{
  const mocap::JsonValue json = mocap::parseJson(mocap::readFileBytes(kIct / "vertex_indices.json"), "vertex_indices.json");
  std::vector<std::string> names;
  for (const mocap::JsonValue& name : json.find("expressions", "vertex indices")->array("expressions"))
    names.push_back(name.string("an expression"));
  return names;
}

mocap::BlendshapeRig loadRig()
{
  return mocap::readObjRig(kIct / "generic_neutral_mesh.obj", kIct / "blendshapes", expressionNames());
}

struct Fixture
{
  mocap::BlendshapeRig rig;
  mocap::MeshBinding binding;
  mocap::Take take{std::vector<std::string>{}, 0, 100.0};
};

// Markers on face vertices (ICT's face region is vertices 0–9408) seen in mm, weights as sums of
// two sines per shape clamped to [0, 1], frame 0 neutral.
const Fixture* fixture()
{
  static const std::unique_ptr<Fixture> f = []() -> std::unique_ptr<Fixture> {
    if (!std::filesystem::exists(kIct / "blendshapes"))
      return nullptr;
    auto fx = std::make_unique<Fixture>();
    fx->rig = loadRig();
    std::vector<std::string> labels;
    std::vector<Eigen::Index> vertices;
    for (Eigen::Index m = 0; m < kMarkers; ++m) {
      vertices.push_back(117 + 233 * m);
      labels.push_back("m" + std::to_string(m));
      fx->binding.markers.push_back({labels.back(), mocap::MeshPoint::atVertex(vertices.back()), 0.0});
    }
    fx->binding.meshVertices = fx->rig.neutral.vertexCount();
    fx->take = mocap::Take(labels, kFrames, 100.0);
    mocap::Random random(3);
    const Eigen::Index shapes = fx->rig.shapeCount();
    Eigen::MatrixXd phase = Eigen::MatrixXd::NullaryExpr(shapes, 4, [&] { return random.uniform(); });
    mocap::MeshVertices posed;
    for (Eigen::Index t = 0; t < kFrames; ++t) {
      Eigen::VectorXd w(shapes);
      for (Eigen::Index s = 0; s < shapes; ++s) {
        const double time = static_cast<double>(t) / 100.0;
        w(s) = t == 0 ? 0.0
                      : std::clamp(0.3 + 0.4 * std::sin(6.0 * phase(s, 0) * time + 6.3 * phase(s, 1)) +
                                       0.3 * std::sin(15.0 * phase(s, 2) * time + 6.3 * phase(s, 3)) - 0.2,
                                   0.0, 1.0);
      }
      fx->rig.evaluate(w, posed);
      for (Eigen::Index m = 0; m < kMarkers; ++m) {
        Eigen::Vector3d p = 10.0 * posed.row(vertices[static_cast<std::size_t>(m)]).transpose();
        if (t > 0)
          p += 0.5 * Eigen::Vector3d(random.normal(), random.normal(), random.normal());
        fx->take.setPosition(t, m, p);
        fx->take.valid()(t, m) = true;
      }
    }
    return fx;
  }();
  return f.get();
}

void BM_RigSetup(benchmark::State& state)
{
  if (!std::filesystem::exists(kIct / "blendshapes")) {
    state.SkipWithError("ICT FaceKit not found");
    return;
  }
  for (auto _ : state)
    benchmark::DoNotOptimize(loadRig());
}

void BM_Solve(benchmark::State& state)
{
  const Fixture* f = fixture();
  if (f == nullptr) {
    state.SkipWithError("ICT FaceKit not found");
    return;
  }
  mocap::BlendshapeSolveOptions options;
  options.method = static_cast<mocap::BlendshapeSolveMethod>(state.range(0));
  const mocap::BlendshapeSolver solver(f->rig, f->binding, f->take, options);
  for (auto _ : state)
    benchmark::DoNotOptimize(solver.solve(f->take));
  state.SetLabel(std::string(mocap::blendshapeSolveMethodName(options.method)));
  state.SetItemsProcessed(state.iterations() * kFrames);
}

// Per frame: the bound points' displacements, AᵀA and its active-set solve from scratch.
void BM_SolveNaiveDenseReference(benchmark::State& state)
{
  const Fixture* f = fixture();
  if (f == nullptr) {
    state.SkipWithError("ICT FaceKit not found");
    return;
  }
  const mocap::BlendshapeSolver solver(f->rig, f->binding, f->take);
  const Eigen::MatrixXd& a = solver.shapeMatrix();
  const Eigen::VectorXd lower = Eigen::VectorXd::Zero(a.cols()), upper = Eigen::VectorXd::Ones(a.cols());
  mocap::PointSet displacements;
  std::vector<bool> present;
  for (auto _ : state)
    for (Eigen::Index t = 0; t < kFrames; ++t) {
      mocap::controlDisplacements(f->take, solver.markers(), solver.neutralFrame(), solver.retarget(), t,
                                  displacements, present);
      const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> interleaved = displacements;
      const Eigen::Map<const Eigen::VectorXd> b(interleaved.data(), interleaved.size());
      benchmark::DoNotOptimize(mocap::solveBoundedLeastSquares(a, b, lower, upper));
    }
  state.SetItemsProcessed(state.iterations() * kFrames);
}

} // namespace

BENCHMARK(BM_RigSetup)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_Solve)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SolveNaiveDenseReference)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
