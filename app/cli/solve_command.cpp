// `mocap solve`: solves a take to the weights of a blendshape rig through a marker binding and
// writes weight curves (CSV), the rig with its animated weights (GLB, FBX) or the solved mesh as a
// PC2 point cache.
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"
#include "leave_out_cli.h"
#include "take_solve.h"

#include "mocap/base/stopwatch.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_writer.h"
#include "mocap/io/weight_output.h"
#include "mocap/io/shipped_retarget_maps.h"
#include "mocap/deform/blendshape_solver.h"
#include "mocap/deform/retarget.h"
#include "mocap/evaluation/deformation_evaluation.h"
#include "mocap/io/fbx_writer.h"
#include "mocap/io/mesh_sequence_writer.h"
#include "mocap/math/key_reduction.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <vector>

namespace mocap::cli {

namespace {

/// The options of `mocap solve`; BlendshapeSolveOptions and LeaveOutOptions hold the defaults the usage shows.
struct SolveArguments
{
  SolveInput input;
  std::string out;
  std::string format = "plain";
  std::optional<std::string> up, units, map;
  std::optional<double> reduce;  // glTF: key tolerance in weight units
  LeaveOutOptions leaveOut;
  bool json = false;
};

/// A shape counts as active when its weight reaches this somewhere in the take.
constexpr double kActiveWeight = 0.01;

struct ResidualSummary
{
  double mean = 0.0, p95 = 0.0, max = 0.0;
};

ResidualSummary summarize(const Eigen::VectorXd& residual)
{
  std::vector<double> values;
  for (const double r : residual)
    if (std::isfinite(r))
      values.push_back(r);
  ResidualSummary s;
  if (values.empty())
    return s;
  std::sort(values.begin(), values.end());
  for (const double v : values)
    s.mean += v / static_cast<double>(values.size());
  s.p95 = values[std::min(values.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(values.size())))];
  s.max = values.back();
  return s;
}

/// The rig's axes and units an FBX declares: --up and --units, else Y-up centimetres (OBJ meshes
/// such as ICT FaceKit's and MediaPipe's).
FbxRigOptions fbxOptions(const SolveArguments& arguments)
{
  FbxRigOptions options;
  if (arguments.up)
    options.up = parseFbxUpAxis(*arguments.up).value();
  if (arguments.units)
    options.unit = parseLengthUnit(*arguments.units).value();
  return options;
}

/// Weight curves for .csv, the rig with its animated weights for .glb and .fbx, else (checkOutput
/// allowed only .pc2) the solved mesh as a point cache. With --reduce, returns the keys kept: for
/// .glb the key frames every curve shares (glTF's weights sampler has one time list), for .fbx the
/// keys of each DeformPercent curve on its own.
std::optional<KeyCount> writeOutput(const std::filesystem::path& out, const SolveArguments& arguments,
                                    const BlendshapeRig& rig, const Take& take, const BlendshapeSolveResult& result,
                                    const Eigen::MatrixXd& head)
{
  if (lowerExtension(out) != "pc2") {
    WeightOutput options;
    options.map = arguments.map;
    options.liveLink = arguments.format == "livelink";
    options.firstFrame = take.firstFrame();
    options.frameRate = take.frameRate();
    options.fbx = fbxOptions(arguments);
    options.reduce = arguments.reduce;
    options.headRotation = head;
    return writeWeightOutput(out, rig, result.weights, options);
  }
  MeshSequenceWriter sink(out, rig.neutral, MeshSequenceFormat::ObjPlusPc2,
                          std::filesystem::path(arguments.input.meshPath).stem().string(),
                          static_cast<float>(take.firstFrame()));
  MeshVertices posed;
  for (Eigen::Index f = 0; f < result.weights.rows(); ++f) {
    rig.evaluate(result.weights.row(f).transpose(), posed);
    sink.add(posed);
  }
  sink.finish();
  return std::nullopt;
}

/// Checked before any work, so a wrong name does not cost a solve.
void checkOutput(const SolveArguments& arguments)
{
  const std::filesystem::path out = arguments.out;
  const std::string extension = lowerExtension(out);
  if (extension != "csv" && extension != "glb" && extension != "fbx" && extension != "pc2")
    throw UsageError("-o must be a .csv (weight curves), .glb or .fbx (rig with animated weights) or .pc2 (solved mesh) "
                     "file, not '" + out.string() + "'");
  if ((arguments.up || arguments.units) && extension != "fbx")
    throw UsageError("--up and --units apply to .fbx output only");
  if (arguments.reduce && extension != "glb" && extension != "fbx")
    throw UsageError("--reduce applies to .glb and .fbx output (curves with keys)");
  if (arguments.format == "livelink" && extension != "csv")
    throw UsageError("--format livelink applies to .csv output only");
  if (arguments.map && extension == "pc2")
    throw UsageError("--map applies to weight curves and rigs (.csv, .glb, .fbx), not to a point cache");
  if (arguments.map)  // a wrong name or a malformed map costs no solve
    (void)readRetargetMapByNameOrPath(*arguments.map);
}

void printSolveJson(const SolveArguments& arguments, const BlendshapeRig& rig, const BlendshapeSolver& solver,
                    const Take& take, const BlendshapeSolveResult& result, double loadSeconds,
                    const std::optional<LeaveOutResult>& quality, const std::optional<KeyCount>& keys,
                    const std::string& note)
{
  const ResidualSummary residual = summarize(result.residual);
  const auto frames = static_cast<double>(result.weights.rows());
  JsonWriter json;
  json.beginObject();
  json.key("method").value(blendshapeSolveMethodName(solver.options().method));
  json.key("lambda").value(result.lambda);
  json.key("lambda_chosen").value(result.lambdaChosen);
  if (solver.options().method == BlendshapeSolveMethod::Temporal) {
    json.key("smoothness").value(solver.options().smoothness);
    json.key("iterations").value(static_cast<std::int64_t>(result.iterations));
  }
  json.key("sparsity").value(solver.options().sparsity);
  json.key("shapes").value(static_cast<std::int64_t>(rig.shapeCount()));
  json.key("markers").value(static_cast<std::int64_t>(solver.markers().size()));
  json.key("frames").value(static_cast<std::int64_t>(result.weights.rows()));
  if (solver.options().actor)
    json.key("neutral_frame").null().key("actor").value(solver.options().actor->name);
  else
    json.key("neutral_frame").value(static_cast<std::int64_t>(take.firstFrame() + solver.neutralFrame()));
  json.key("held_frames").value(static_cast<std::int64_t>(std::count(result.held.begin(), result.held.end(), true)));
  json.key("rig_load_seconds").value(loadSeconds);
  json.key("setup_seconds").value(solver.setupSeconds());
  json.key("solve_seconds").value(result.solveSeconds);
  json.key("frames_per_second").value(result.solveSeconds > 0.0 ? frames / result.solveSeconds : 0.0);
  json.key("residual_mm").beginObject();
  json.key("mean").value(residual.mean);
  json.key("p95").value(residual.p95);
  json.key("max").value(residual.max);
  json.endObject();
  if (quality) {
    json.key("leave_out_error_mm").value(quality->meanError);
    writeLeaveOutJson(json, *quality, arguments.leaveOut, solver.labels());
  } else {
    json.key("leave_out_error_mm").null();
  }
  json.key("active_shapes").beginArray();
  for (Eigen::Index s = 0; s < rig.shapeCount(); ++s) {
    const double peak = result.weights.rows() > 0 ? result.weights.col(s).maxCoeff() : 0.0;
    if (peak < kActiveWeight)
      continue;
    json.beginObject();
    json.key("name").value(rig.shapes[static_cast<std::size_t>(s)].name);
    json.key("max").value(peak);
    json.key("mean").value(result.weights.col(s).mean());
    json.endObject();
  }
  json.endArray();
  if (keys) {
    json.key("key_reduction").beginObject();
    json.key("tolerance").value(*arguments.reduce);
    json.key("keyed").value(lowerExtension(arguments.out) == "glb" ? "frames shared by every shape" : "each curve");
    json.key("keys_before").value(static_cast<std::int64_t>(keys->before));
    json.key("keys_after").value(static_cast<std::int64_t>(keys->after));
    json.key("max_error").value(keys->maxError);
    json.endObject();
  }
  json.key("notes").beginArray();
  if (!note.empty())
    json.value(note);
  json.endArray();
  json.key("output").value(arguments.out);
  json.endObject();
  std::cout << json.str() << '\n';
}

int runSolve(const SolveArguments& arguments)
{
  checkOutput(arguments);
  const SolvedTake solved = solveInputTake(arguments.input, [&](const BlendshapeRig& rig) {
    if (lowerExtension(arguments.out) != "pc2") {
      WeightOutput mapping;
      mapping.map = arguments.map;
      mapping.liveLink = arguments.format == "livelink";
      checkWeightOutput(rig, mapping);
    }
  });
  const BlendshapeRig& rig = *solved.rig;
  const Take& take = solved.take;
  const BlendshapeSolver& solver = *solved.solver;
  const BlendshapeSolveResult& result = solved.result;
  const double loadSeconds = solved.rigLoadSeconds;
  const std::optional<KeyCount> keys = writeOutput(arguments.out, arguments, rig, take, result, solved.headRotation());
  std::optional<LeaveOutResult> quality;
  if (arguments.leaveOut.fraction > 0.0)
    quality = evaluateBlendshapeLeaveOut(solver, take, arguments.leaveOut);

  if (arguments.json) {
    printSolveJson(arguments, rig, solver, take, result, loadSeconds, quality, keys, solved.unstabilizedHeadNote());
    return kExitOk;
  }
  const ResidualSummary residual = summarize(result.residual);
  const auto held = std::count(result.held.begin(), result.held.end(), true);
  std::cout << "solved " << result.weights.rows() << " frames to " << rig.shapeCount() << " shapes from "
            << solver.markers().size() << " markers (" << arguments.input.method << ", λ " << result.lambda
            << (result.lambdaChosen ? " by GCV" : "") << ")\nrig " << fixedNumber(loadSeconds, 3) << " s, set-up "
            << fixedNumber(solver.setupSeconds(), 3) << " s, solve " << fixedNumber(result.solveSeconds, 3)
            << " s\nmarker residual " << fixedNumber(residual.mean, 2) << " mm mean, " << fixedNumber(residual.p95, 2)
            << " mm p95, " << fixedNumber(residual.max, 2) << " mm max\n";
  if (const std::string note = solved.unstabilizedHeadNote(); !note.empty())
    std::cout << "note: " << note << '\n';
  if (held > 0)
    std::cout << "warning: " << held << " frames had too few markers and hold the previous frame's weights\n";
  if (quality)
    std::cout << "leave-" << quality->hidden.size() << "-markers-out error " << fixedNumber(quality->meanError, 2)
              << " mm mean (face at rest: " << fixedNumber(quality->restError, 2) << " mm)\n";
  if (keys)
    std::cout << "kept " << keys->after << " of " << keys->before << " keys, largest error "
              << fixedNumber(keys->maxError, 4) << " (tolerance " << *arguments.reduce << ")\n";
  std::cout << "wrote " << arguments.out << '\n';
  return kExitOk;
}

} // namespace

Command addSolve(CLI::App& mocap)
{
  CLI::App* command = mocap.add_subcommand(
      "solve", "solve the take to a blendshape rig's weights; weight curves (CSV), animated rig (GLB, FBX) or mesh (PC2)");
  const auto a = std::make_shared<SolveArguments>();
  SolveInput& input = a->input;
  BlendshapeSolveOptions& settings = input.settings;
  command->add_option("--mesh", input.meshPath, "the rig: its neutral (.obj, .ply) with --shapes, or a glTF rig (.glb, .gltf)")
      ->required()
      ->type_name("NEUTRAL.obj|RIG.glb");
  command->add_option("--shapes", input.shapesPath, "folder with one OBJ per shape, named after it")->type_name("DIR");
  command->add_option("--binding", input.bindingPath, "the binding mocap bind wrote")->required()->type_name("BIND.json");
  command->add_option("--take", input.takePath, "the take to solve")->required()->type_name("TAKE");
  wholeNumberIn(command->add_option("--neutral", settings.neutralFrame,
                                    "the neutral frame (default: the first with every bound marker)")
                    ->type_name("FRAME"),
                -(1LL << 40), 1LL << 40);
  command->add_option("--stabilize", input.stabilize, "head-mounted markers whose motion is removed first")
      ->type_name("LABELS");
  command->add_option("--actor", input.actor,
                      "an actor profile (mocap actor): its neutral instead of --neutral, weights in its range")
      ->type_name("ACTOR.json");
  oneOf(command->add_option("--method", input.method, "solve"), blendshapeSolveMethodNames())->capture_default_str();
  numberIn(command->add_option("--lambda", settings.lambda,
                               "ridge weight λ relative to the shapes' mean squared motion (default: by GCV)")
               ->type_name("L"),
           0.0, 1e6);
  numberIn(command->add_option("--smoothness", settings.smoothness,
                               "temporal: weight of the weights' second differences, as at 100 Hz")
               ->type_name("S"),
           0.0, 1e6)
      ->capture_default_str();
  numberIn(command->add_option("--sparsity", settings.sparsity, "L1 weight pulling unused shapes to 0")->type_name("S"),
           0.0, 1e3)
      ->capture_default_str();
  command->add_option("--only", input.only, "solve only these shapes")->type_name("NAME,...");
  oneOf(command->add_option("--format", a->format,
                            "CSV layout: Frame,Time,<shape>,… or Live Link Face's (52 ARKit curves in the app's "
                            "order, head and eye rotations, timecode)"),
        std::string("plain|livelink"))
      ->capture_default_str();
  command->add_option("--map", a->map,
                      "retarget the weights onto a target rig's channels: a shipped map (ict_to_arkit, arkit_to_ict, "
                      "ict_identity) or a map file; Live Link output defaults to ict_to_arkit for ICT names")
      ->type_name("NAME|MAP.json");
  addLeaveOutOptions(*command, a->leaveOut);
  command->add_option("-o", a->out,
                      "weight curves (.csv), the rig with animated weights (.glb, .fbx) or the solved mesh (.pc2, plus "
                      "OUT.obj)")
      ->required()
      ->type_name("OUT.csv|OUT.glb|OUT.fbx|OUT.pc2");
  oneOf(command->add_option("--up", a->up, "FBX: the rig's up axis, declared in the file (default y)"),
        std::string("y|z"));
  oneOf(command->add_option("--units", a->units, "FBX: the rig's length unit, declared in the file (default cm)"),
        std::string("cm|mm"));
  numberIn(command->add_option("--reduce", a->reduce,
                               "glTF, FBX: keep the fewest keys whose linear interpolation stays within this many "
                               "weight units of every solved frame (glTF: key frames shared by every shape; FBX: "
                               "each shape's curve on its own)")
               ->type_name("TOLERANCE"),
           0.0, 1.0);
  command->add_flag("--json", a->json, "print JSON: λ, timing, marker residual, leave-out error, active shapes");
  return {command, [a] { return runSolve(*a); }};
}

} // namespace mocap::cli
