// `mocap deform`: drives a face mesh with a take through a marker binding (RBF or Laplacian
// deformation) and writes a PC2 point cache or one mesh per frame.
#include "take_input.h"
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"
#include "frame_range.h"
#include "leave_out_cli.h"

#include "mocap/evaluation/deformation_evaluation.h"
#include "mocap/base/stopwatch.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/deform/face_rig.h"
#include "mocap/deform/retarget.h"
#include "mocap/deform/laplacian_weights.h"
#include "mocap/base/json_writer.h"
#include "mocap/deform/laplacian_deformer.h"
#include "mocap/io/mesh_io.h"
#include "mocap/io/mesh_sequence_writer.h"
#include "mocap/deform/rbf_deformer.h"
#include "mocap/io/take_io.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace mocap::cli {

namespace {

/// The options of `mocap deform`; FaceRigOptions and LeaveOutOptions hold the defaults the usage shows.
struct DeformArguments
{
  std::string meshPath, bindingPath, takePath, out;
  FaceRigOptions settings;
  std::string method = std::string(deformMethodName(FaceRigOptions{}.method));
  std::string kernel = std::string(rbfKernelName(RbfOptions{}.kernel));
  bool noAffine = false;
  std::string up = std::string(1, static_cast<char>('x' + RbfOptions{}.upAxis));
  std::string weights = std::string(laplacianWeightsName(LaplacianOptions{}.weights));
  std::string scale = std::string(retargetScaleName(FaceRigOptions{}.scale));
  std::optional<std::string> stabilize, frames;
  LeaveOutOptions leaveOut;
  bool ply = false;
  bool json = false;
};

FaceRigOptions parseSettings(const DeformArguments& arguments)
{
  FaceRigOptions settings = arguments.settings;
  settings.method = parseDeformMethod(arguments.method).value();
  settings.rbf.kernel = parseRbfKernel(arguments.kernel).value();
  settings.rbf.affine = !arguments.noAffine;
  settings.rbf.upAxis = arguments.up[0] - 'x';
  settings.laplacian.weights = parseLaplacianWeights(arguments.weights).value();
  if (settings.rotations > 0 && settings.method != DeformMethod::Laplacian)
    throw UsageError("--rotations needs --method laplacian");
  settings.scale = parseRetargetScale(arguments.scale).value();
  return settings;
}

int runDeform(const DeformArguments& arguments)
{
  const std::string& meshPath = arguments.meshPath;
  const std::string& bindingPath = arguments.bindingPath;
  const std::string& takePath = arguments.takePath;
  const std::filesystem::path out = arguments.out;
  const FaceRigOptions settings = parseSettings(arguments);
  LeaveOutOptions leaveOut = arguments.leaveOut;
  leaveOut.rotations = settings.rotations;

  const Mesh mesh = readMesh(meshPath);
  Take take = readInputTake(takePath);
  const auto [begin, end] = parseFrameRange(arguments.frames, take);  // a bad range fails before the setup
  if (arguments.stabilize)
    (void)stabilizeTake(take, splitList(*arguments.stabilize, "--stabilize"));
  FaceRig rig(mesh, readBinding(bindingPath, mesh.vertexCount()), take, settings);
  const bool laplacian = settings.method == DeformMethod::Laplacian;
  const std::vector<Eigen::Index>& markers = rig.markers();
  const Eigen::Index neutral = rig.neutralFrame();
  const Retarget& retarget = rig.retarget();
  const double setupSeconds = rig.setupSeconds();

  const MeshSequenceFormat format = lowerExtension(out) == "pc2" ? MeshSequenceFormat::ObjPlusPc2
                                     : arguments.ply            ? MeshSequenceFormat::PlySequence
                                                                 : MeshSequenceFormat::ObjSequence;
  MeshSequenceWriter sink(out, mesh, format, std::filesystem::path(meshPath).stem().string(),
                          static_cast<float>(take.firstFrame() + begin));
  std::vector<double> frameSeconds;
  Eigen::Index framesMissingControls = 0;
  MeshVertices deformed;
  for (Eigen::Index f = begin; f < end; ++f) {
    const Stopwatch frameTime;
    framesMissingControls += rig.deform(take, f, deformed) ? 0 : 1;
    frameSeconds.push_back(frameTime.seconds());
    sink.add(deformed);
  }
  sink.finish();
  std::optional<LeaveOutResult> quality;
  if (leaveOut.fraction > 0.0)
    quality = evaluateLeaveOut(take, markers, rig.points(), neutral, retarget, mesh.vertices, rig.factory(), leaveOut);

  std::vector<double> sorted = frameSeconds;
  std::sort(sorted.begin(), sorted.end());
  double mean = 0.0;
  for (const double s : sorted)
    mean += s / static_cast<double>(sorted.size());
  const double p95 = sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(sorted.size())))];
  const std::string variant = laplacian ? std::string(laplacianWeightsName(settings.laplacian.weights))
                                                 : std::string(rbfKernelName(settings.rbf.kernel));
  if (arguments.json) {
    JsonWriter json;
    json.beginObject();
    json.key("vertices").value(static_cast<std::int64_t>(mesh.vertexCount()));
    json.key("frames").value(static_cast<std::int64_t>(frameSeconds.size()));
    json.key("setup_seconds").value(setupSeconds);
    json.key("frame_seconds_mean").value(mean);
    json.key("frame_seconds_p95").value(p95);
    if (quality)
      json.key("leave_out_error_mm").value(quality->meanError);
    else
      json.key("leave_out_error_mm").null();
    json.key("method").value(deformMethodName(settings.method));
    json.key(laplacian ? "weights" : "kernel").value(variant);
    if (laplacian) {
      json.key("constraint_weight").value(settings.laplacian.constraintWeight);
      json.key("rotations").value(settings.rotations);
    } else {
      json.key("radius").value(settings.rbf.radius);
      json.key("affine").value(settings.rbf.affine);
      json.key("regions").value(settings.rbf.regions);
    }
    json.key("controls").value(static_cast<std::int64_t>(markers.size()));
    json.key("neutral_frame").value(static_cast<std::int64_t>(take.firstFrame() + neutral));
    json.key("scale").value(retargetScaleName(settings.scale));
    json.key("scale_factors").beginArray();
    for (int a = 0; a < 3; ++a)
      json.value(retarget.axisScale(a));
    json.endArray();
    json.key("frames_missing_controls").value(static_cast<std::int64_t>(framesMissingControls));
    if (quality)
      writeLeaveOutJson(json, *quality, leaveOut, rig.labels());
    json.key("output").value(out.string());
    json.endObject();
    std::cout << json.str() << '\n';
  } else {
    std::cout << "deformed " << frameSeconds.size() << " frames of a " << mesh.vertexCount() << "-vertex mesh with "
              << markers.size() << " controls (" << (laplacian ? "laplacian, " : "rbf, ") << variant
              << ")\nset-up " << fixedNumber(setupSeconds, 3) << " s; per frame " << fixedNumber(1e3 * mean, 3)
              << " ms mean, " << fixedNumber(1e3 * p95, 3) << " ms p95\n";
    if (quality)
      std::cout << "leave-" << quality->hidden.size() << "-markers-out error " << fixedNumber(quality->meanError, 2)
                << " mm mean, " << fixedNumber(quality->rmsError, 2) << " mm RMS (mesh at rest: "
                << fixedNumber(quality->restError, 2) << " mm)\n";
    std::cout << "wrote " << out.string() << '\n';
  }
  return kExitOk;
}

} // namespace

Command addDeform(CLI::App& mocap)
{
  CLI::App* command =
      mocap.add_subcommand("deform", "deform a face mesh by the take; PC2 cache or one mesh per frame");
  const auto a = std::make_shared<DeformArguments>();
  FaceRigOptions& settings = a->settings;
  command->add_option("--mesh", a->meshPath, "the face mesh (.obj, .ply, or a glTF rig's neutral: .glb, .gltf)")->required()->type_name("FACE.obj");
  command->add_option("--binding", a->bindingPath, "the binding mocap bind wrote")->required()->type_name("BIND.json");
  command->add_option("--take", a->takePath, "the take that drives the mesh")->required()->type_name("TAKE");
  wholeNumberIn(command->add_option("--neutral", settings.neutralFrame,
                                    "the neutral frame (default: the first with every bound marker)")
                    ->type_name("FRAME"),
                -(1LL << 40), 1LL << 40);
  oneOf(command->add_option("--method", a->method, "deformation"), deformMethodNames())->capture_default_str();
  oneOf(command->add_option("--kernel", a->kernel, "RBF kernel"), rbfKernelNames())
      ->capture_default_str();
  numberIn(command->add_option("--radius", settings.rbf.radius, "RBF radius c, in mesh units")->type_name("C"), 1e-9,
           1e9)
      ->capture_default_str();
  command->add_flag("--regions", settings.rbf.regions, "RBF per top/middle/bottom region, blended at the borders");
  command->add_flag("--no-affine", a->noAffine, "RBF without the affine term");
  oneOf(command->add_option("--up", a->up, "the mesh's up axis, for --regions"), {"x", "y", "z"})
      ->capture_default_str();
  oneOf(command->add_option("--weights", a->weights, "Laplacian weights"), laplacianWeightsNames())
      ->capture_default_str();
  numberIn(command->add_option("--constraint-weight", settings.laplacian.constraintWeight,
                               "Laplacian weight of the marker constraints")
               ->type_name("W"),
           1e-6, 1e6)
      ->capture_default_str();
  wholeNumberIn(command->add_option("--rotations", settings.rotations,
                                    "Laplacian rotation-aware iterations per frame (needs --method laplacian)")
                    ->type_name("N"),
                0, 100)
      ->capture_default_str();
  command->add_option("--stabilize", a->stabilize, "head-mounted markers whose motion is removed first")
      ->type_name("LABELS");
  oneOf(command->add_option("--scale", a->scale, "marker displacements to mesh scale"), retargetScaleNames())
      ->capture_default_str();
  command->add_option("--frames", a->frames, "the frames deformed, as the take numbers them (default: all)")
      ->type_name("FIRST:LAST");
  addLeaveOutOptions(*command, a->leaveOut);
  command->add_flag("--ply", a->ply, "write PLY frames (with a folder output)");
  command->add_option("-o", a->out, "a .pc2 point cache (plus OUT.obj), or a folder of one mesh per frame")
      ->required()
      ->type_name("OUT.pc2|OUTDIR");
  command->add_flag("--json", a->json, "print JSON: timing and the leave-markers-out error");
  return {command, [a] { return runDeform(*a); }};
}

} // namespace mocap::cli
