#pragma once

#include "mocap/base/job_control.h"
#include "mocap/io/fbx_document.h"
#include "mocap/math/key_reduction.h"
#include "mocap/model/mesh.h"
#include "mocap/model/take.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mocap::ui {

/// Fills `vertices` (#vertices × 3) with the deformed mesh at take frame index `frame` (0-based).
/// Called on the export's worker thread: it must not touch widgets or data the UI thread changes
/// meanwhile (capture copies).
using MeshFrameSource = std::function<void(Eigen::Index frame, MeshVertices& vertices)>;

/// What the Export Animation dialog writes.
enum class AnimationFormat
{
  Bvh,          ///< the markers as a BVH skeleton (bvh_writer.h)
  ObjSequence,  ///< one OBJ of the deformed mesh per frame, in a folder
  ObjPlusPc2,   ///< a PC2 point cache and the rest mesh as OBJ beside it
  Fbx,          ///< the markers as animated nulls (fbx_writer.h), as `mocap convert TAKE OUT.fbx`
};

/// True for the formats that write the markers (BVH, FBX), false for the deformed mesh's.
[[nodiscard]] inline bool markerFormat(AnimationFormat format)
{
  return format == AnimationFormat::Bvh || format == AnimationFormat::Fbx;
}

/// One export, holding copies of its data so it can run on a worker thread while the take is edited.
struct AnimationExportJob
{
  AnimationFormat format = AnimationFormat::Bvh;
  std::filesystem::path output;  ///< the .bvh or .pc2 file, or the OBJ sequence's folder
  Take markers;                  ///< BVH, FBX: the frames to write (e.g. sliceFrames of the take)
  FbxUpAxis up = FbxUpAxis::Z;   ///< FBX: the take's up axis, declared in the file (`--up`)
  std::optional<double> reduceMm;  ///< FBX: keys within this many mm of every frame (`--reduce`), else every frame
  Mesh mesh;                     ///< mesh formats: the mesh that `source` deforms
  MeshFrameSource source;
  std::string meshName = "mesh";  ///< file-name stem of the sequence files
  Eigen::Index begin = 0;         ///< mesh formats: take frame indices [begin, end) given to `source`
  Eigen::Index end = 0;
  float startFrame = 1.0f;  ///< PC2 header: the frame number of `begin`

  [[nodiscard]] Eigen::Index frameCount() const
  {
    return markerFormat(format) ? markers.frameCount() : end - begin;
  }
};

enum class ExportStatus
{
  Done,
  Cancelled,
  Failed,
};

struct ExportOutcome
{
  ExportStatus status = ExportStatus::Done;
  std::string error;  ///< why it failed (Failed only)
  std::optional<KeyCount> keys;  ///< FBX with reduceMm: the keys kept, the largest error in mm
};

/// The existing files `job` would replace (the BVH or PC2 file, the rest OBJ beside a cache, the
/// sequence's NAME_0001.obj… in its folder), so the dialog can ask first. O(#frames) file checks
/// for an OBJ sequence, else O(1).
[[nodiscard]] std::vector<std::filesystem::path> filesReplacedBy(const AnimationExportJob& job);

/// Runs `job`, reporting the frames done to `control` and checking its cancel between frames (a
/// cancelled export returns Cancelled rather than throwing). A cancelled or failed export leaves no
/// output behind (MeshSequenceWriter removes what it wrote; BVH and FBX are written atomically at
/// the end). Never throws: errors come back in the outcome. O(#frames · (source cost + #vertices)) for
/// the mesh formats, O(#frames · #markers) for BVH.
[[nodiscard]] ExportOutcome runAnimationExport(const AnimationExportJob& job, const JobControl& control);

} // namespace mocap::ui
