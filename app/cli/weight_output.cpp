#include "weight_output.h"

#include "cli_error.h"

#include "mocap/base/file_io.h"
#include "mocap/io/gltf_writer.h"
#include "mocap/io/live_link_face_csv.h"
#include "mocap/io/live_link_face_map.h"
#include "mocap/io/shipped_retarget_maps.h"
#include "mocap/io/weights_csv_writer.h"

namespace mocap::cli {

namespace {

/// The map onto Live Link Face's curves: --map's, else the default for the rig's names; checked.
RetargetMap liveLinkMap(const BlendshapeRig& rig, const WeightOutput& options)
{
  RetargetMap map = options.map ? readRetargetMapByNameOrPath(*options.map) : liveLinkFaceMapForRig(rig.shapeNames());
  checkLiveLinkFaceChannels(map);
  return map;
}

void writeLiveLink(const std::filesystem::path& out, const BlendshapeRig& rig,
                   const Eigen::Ref<const Eigen::MatrixXd>& weights, const WeightOutput& options)
{
  const RetargetMap map = liveLinkMap(rig, options);
  const MappedWeights mapped = applyRetargetMap(map, rig.shapeNames(), weights);
  writeLiveLinkFaceCsv(out, liveLinkFaceRecording(mapped.names, mapped.weights, options.frameRate,
                                                  options.headRotation));
}

void writeMapped(const std::filesystem::path& out, const std::string& extension, const BlendshapeRig& rig,
                 const Eigen::Ref<const Eigen::MatrixXd>& weights, const WeightOutput& options)
{
  if (extension == "csv")
    writeWeightsCsv(out, rig.shapeNames(), weights, options.firstFrame, options.frameRate);
  else if (extension == "glb")
    writeRigGlb(out, rig, weights, options.frameRate, options.keys);
  else if (extension == "fbx")
    writeRigFbx(out, rig, weights, options.frameRate, options.fbx);
  else
    throw UsageError("weights are written to .csv, .glb or .fbx, not '" + out.string() + "'");
}

} // namespace

void writeWeightOutput(const std::filesystem::path& out, const BlendshapeRig& rig,
                       const Eigen::Ref<const Eigen::MatrixXd>& weights, const WeightOutput& options)
{
  const std::string extension = lowerExtension(out);
  if (extension == "csv" && options.liveLink) {
    writeLiveLink(out, rig, weights, options);
    return;
  }
  if (!options.map) {
    writeMapped(out, extension, rig, weights, options);
    return;
  }
  const RetargetMap map = readRetargetMapByNameOrPath(*options.map);
  const MappedWeights mapped = applyRetargetMap(map, rig.shapeNames(), weights);
  writeMapped(out, extension, retargetedRig(map, rig), mapped.weights, options);
}

void checkWeightOutput(const BlendshapeRig& rig, const WeightOutput& options)
{
  const Eigen::MatrixXd noFrames(0, rig.shapeCount());
  if (options.liveLink)
    (void)applyRetargetMap(liveLinkMap(rig, options), rig.shapeNames(), noFrames);
  else if (options.map)
    (void)applyRetargetMap(readRetargetMapByNameOrPath(*options.map), rig.shapeNames(), noFrames);
}

void checkMapArgument(const std::optional<std::string>& map)
{
  if (map)
    (void)readRetargetMapByNameOrPath(*map);
}

} // namespace mocap::cli
