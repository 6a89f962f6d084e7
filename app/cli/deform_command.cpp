// `mocap deform`: drives a face mesh with a take through a marker binding (RBF or Laplacian
// deformation) and writes a PC2 point cache or one mesh per frame.
#include "arguments.h"
#include "cli_error.h"

#include "mocap/evaluation/deformation_evaluation.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/deform/face_rig.h"
#include "mocap/base/json_writer.h"
#include "mocap/deform/laplacian_deformer.h"
#include "mocap/io/mesh_io.h"
#include "mocap/io/mesh_sequence_writer.h"
#include "mocap/deform/rbf_deformer.h"
#include "mocap/io/take_io.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace mocap::cli {

/// `mocap deform --mesh FACE.obj --binding BIND.json --take TAKE [--neutral FRAME]
/// [--method rbf|laplacian] [--kernel exp|gaussian|biharmonic|thin-plate] [--radius C] [--regions]
/// [--no-affine] [--up x|y|z] [--weights uniform|cotangent|mean-value] [--constraint-weight W]
/// [--stabilize LABELS] [--scale uniform|per-axis] [--frames FIRST:LAST] [--leave-out FRACTION]
/// [--seed S] [--ply] -o OUT.pc2|OUTDIR [--json]`. Returns the exit code.
int runDeform(const std::vector<std::string>& args);

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string required(const Arguments& arguments, const std::string& option)
{
  const auto value = arguments.value(option);
  if (!value)
    throw UsageError(option + " is required");
  return *value;
}

FaceRigOptions parseSettings(const Arguments& arguments)
{
  FaceRigOptions settings;
  const std::string method = arguments.value("--method").value_or("rbf");
  const auto parsedMethod = parseDeformMethod(method);
  if (!parsedMethod)
    throw UsageError("--method must be rbf or laplacian, not '" + method + "'");
  settings.method = *parsedMethod;
  if (const auto kernel = arguments.value("--kernel")) {
    const auto parsed = parseRbfKernel(*kernel);
    if (!parsed)
      throw UsageError("--kernel must be exp, gaussian, biharmonic or thin-plate, not '" + *kernel + "'");
    settings.rbf.kernel = *parsed;
  }
  if (const auto radius = arguments.number("--radius", 1e-9, 1e9))
    settings.rbf.radius = *radius;
  settings.rbf.regions = arguments.has("--regions");
  settings.rbf.affine = !arguments.has("--no-affine");
  if (const auto up = arguments.value("--up")) {
    if (*up != "x" && *up != "y" && *up != "z")
      throw UsageError("--up must be x, y or z");
    settings.rbf.upAxis = (*up)[0] - 'x';
  }
  if (const auto weights = arguments.value("--weights")) {
    const auto parsed = parseLaplacianWeights(*weights);
    if (!parsed)
      throw UsageError("--weights must be uniform, cotangent or mean-value, not '" + *weights + "'");
    settings.laplacian.weights = *parsed;
  }
  if (const auto w = arguments.number("--constraint-weight", 1e-6, 1e6))
    settings.laplacian.constraintWeight = *w;
  settings.rotations = static_cast<int>(arguments.integer("--rotations", 0, 100).value_or(0));
  if (settings.rotations > 0 && settings.method != DeformMethod::Laplacian)
    throw UsageError("--rotations needs --method laplacian");
  if (const auto text = arguments.value("--scale")) {
    const auto parsed = parseRetargetScale(*text);
    if (!parsed)
      throw UsageError("--scale must be uniform or per-axis, not '" + *text + "'");
    settings.scale = *parsed;
  }
  settings.neutralFrame = arguments.integer("--neutral", -(1LL << 40), 1LL << 40);
  return settings;
}

std::pair<Eigen::Index, Eigen::Index> frameRange(const Arguments& arguments, const Take& take)
{
  const auto text = arguments.value("--frames");
  if (!text)
    return {0, take.frameCount()};
  const std::size_t colon = text->find(':');
  long long first = 0, last = 0;
  if (colon == std::string::npos || std::sscanf(text->c_str(), "%lld:%lld", &first, &last) != 2)
    throw UsageError("--frames needs FIRST:LAST frame numbers, not '" + *text + "'");
  const long long begin = first - take.firstFrame(), end = last - take.firstFrame() + 1;
  if (begin < 0 || end > take.frameCount() || begin >= end)
    throw UsageError("--frames " + *text + " is outside the take or empty");
  return {static_cast<Eigen::Index>(begin), static_cast<Eigen::Index>(end)};
}

} // namespace

int runDeform(const std::vector<std::string>& args)
{
  const Arguments arguments(args, {"--json", "--regions", "--ply", "--no-affine"},
                            {"--mesh", "--binding", "--take", "--neutral", "--method", "--kernel", "--radius",
                             "--weights", "--constraint-weight", "--stabilize", "--scale", "-o", "--leave-out",
                             "--seed", "--frames", "--up", "--rotations"});
  arguments.expectPositionals(0, "no positional arguments (--mesh, --binding, --take and -o)");
  const std::string meshPath = required(arguments, "--mesh");
  const std::string bindingPath = required(arguments, "--binding");
  const std::string takePath = required(arguments, "--take");
  const std::filesystem::path out = required(arguments, "-o");
  const FaceRigOptions settings = parseSettings(arguments);
  LeaveOutOptions leaveOut;
  leaveOut.fraction = arguments.number("--leave-out", 0.0, 0.9).value_or(0.2);
  leaveOut.seed = static_cast<std::uint64_t>(arguments.integer("--seed", 0, 1LL << 62).value_or(1));
  leaveOut.rotations = settings.rotations;

  const Mesh mesh = readMesh(meshPath);
  std::vector<std::string> warnings;
  Take take = readTake(takePath, &warnings);
  for (const auto& w : warnings)
    std::cerr << takePath << ": warning: " << w << '\n';
  if (const auto labels = arguments.value("--stabilize"))
    (void)stabilizeTake(take, splitList(*labels, "--stabilize"));
  FaceRig rig(mesh, readBinding(bindingPath, mesh.vertexCount()), take, settings);
  const bool laplacian = settings.method == DeformMethod::Laplacian;
  const std::vector<Eigen::Index>& markers = rig.markers();
  const Eigen::Index neutral = rig.neutralFrame();
  const Retarget& retarget = rig.retarget();
  const double setupSeconds = rig.setupSeconds();

  const auto [begin, end] = frameRange(arguments, take);
  const MeshSequenceFormat format = lowerExtension(out) == "pc2" ? MeshSequenceFormat::ObjPlusPc2
                                     : arguments.has("--ply")    ? MeshSequenceFormat::PlySequence
                                                                 : MeshSequenceFormat::ObjSequence;
  MeshSequenceWriter sink(out, mesh, format, std::filesystem::path(meshPath).stem().string(),
                          static_cast<float>(take.firstFrame() + begin));
  std::vector<double> frameSeconds;
  Eigen::Index framesMissingControls = 0;
  MeshVertices deformed;
  for (Eigen::Index f = begin; f < end; ++f) {
    const Clock::time_point start = Clock::now();
    framesMissingControls += rig.deform(take, f, deformed) ? 0 : 1;
    frameSeconds.push_back(secondsSince(start));
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
  if (arguments.has("--json")) {
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
    if (quality) {
      json.key("leave_out").beginObject();
      json.key("fraction").value(leaveOut.fraction);
      json.key("seed").value(static_cast<std::int64_t>(leaveOut.seed));
      json.key("hidden").beginArray();
      for (const Eigen::Index h : quality->hidden)
        json.value(rig.labels()[static_cast<std::size_t>(h)]);
      json.endArray();
      json.key("samples").value(static_cast<std::int64_t>(quality->samples));
      json.key("rms_mm").value(quality->rmsError);
      json.key("max_mm").value(quality->maxError);
      json.key("rest_error_mm").value(quality->restError);
      json.endObject();
    }
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

} // namespace mocap::cli
