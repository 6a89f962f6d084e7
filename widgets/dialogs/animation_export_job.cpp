#include "dialogs/animation_export_job.h"

#include "mocap/io/bvh_writer.h"
#include "mocap/io/fbx_writer.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/io/mesh_sequence_writer.h"

#include <cstdio>
#include <system_error>

namespace mocap::ui {

namespace {

ExportStatus writeBvhFile(const AnimationExportJob& job, const JobControl& control)
{
  const std::string text = formatBvh(job.markers);
  if (control.cancelled())
    return ExportStatus::Cancelled;
  writeFileAtomically(job.output, text);
  control.reportNow(1.0);
  return ExportStatus::Done;
}

/// The markers as FBX, with reduceMm each curve keyed within it (in the take's units, as `mocap
/// convert --reduce` does); the keys kept go to `keys`, their largest error in mm.
ExportStatus writeFbxFile(const AnimationExportJob& job, const JobControl& control, std::optional<KeyCount>& keys)
{
  const double mmPerUnit = millimetresPer(job.markers.units());
  KeyCount counted;
  FbxCurveKeys reduction;
  if (job.reduceMm)
    reduction = {*job.reduceMm / mmPerUnit, &counted};
  const std::string text = markersFbx(job.markers, job.up, reduction);
  if (control.cancelled())
    return ExportStatus::Cancelled;
  writeFileAtomically(job.output, text);
  if (job.reduceMm) {
    counted.maxError *= mmPerUnit;
    keys = counted;
  }
  control.reportNow(1.0);
  return ExportStatus::Done;
}

ExportStatus writeMeshFrames(const AnimationExportJob& job, const JobControl& control)
{
  if (!job.source)
    throw InvalidArgument("no deformed mesh to export: load a face mesh first");
  const MeshSequenceFormat format =
      job.format == AnimationFormat::ObjPlusPc2 ? MeshSequenceFormat::ObjPlusPc2 : MeshSequenceFormat::ObjSequence;
  MeshSequenceWriter writer(job.output, job.mesh, format, job.meshName, job.startFrame);
  MeshVertices vertices = job.mesh.vertices;
  for (Eigen::Index f = job.begin; f < job.end; ++f) {
    if (control.cancelled())
      return ExportStatus::Cancelled;  // the writer removes what it wrote
    job.source(f, vertices);
    writer.add(vertices);
    control.report(static_cast<double>(f + 1 - job.begin) / static_cast<double>(job.end - job.begin));
  }
  writer.finish();
  control.reportNow(1.0);
  return ExportStatus::Done;
}

} // namespace

std::vector<std::filesystem::path> filesReplacedBy(const AnimationExportJob& job)
{
  std::vector<std::filesystem::path> files;
  std::error_code error;  // an unreadable path is not "existing": the export reports it
  const auto keepIfFile = [&](const std::filesystem::path& path) {
    if (std::filesystem::is_regular_file(path, error))
      files.push_back(path);
  };
  switch (job.format) {
  case AnimationFormat::Bvh:
  case AnimationFormat::Fbx:
    keepIfFile(job.output);
    break;
  case AnimationFormat::ObjPlusPc2:
    keepIfFile(job.output);
    keepIfFile(MeshSequenceWriter::restObjPath(job.output));
    break;
  case AnimationFormat::ObjSequence:
    if (!std::filesystem::is_directory(job.output, error))
      break;
    for (long long n = 1; n <= job.frameCount(); ++n) {  // the writer's NAME_0001.obj numbering
      char number[32];
      std::snprintf(number, sizeof number, "_%04lld.obj", n);
      keepIfFile(job.output / (job.meshName + number));
    }
    break;
  }
  return files;
}

ExportOutcome runAnimationExport(const AnimationExportJob& job, const JobControl& control)
{
  ExportOutcome outcome;
  try {
    switch (job.format) {
    case AnimationFormat::Bvh: outcome.status = writeBvhFile(job, control); break;
    case AnimationFormat::Fbx: outcome.status = writeFbxFile(job, control, outcome.keys); break;
    case AnimationFormat::ObjSequence:
    case AnimationFormat::ObjPlusPc2: outcome.status = writeMeshFrames(job, control); break;
    }
  } catch (const std::exception& e) {  // nothing may throw across the worker boundary
    outcome.status = ExportStatus::Failed;
    outcome.error = e.what();
  }
  return outcome;
}

} // namespace mocap::ui
