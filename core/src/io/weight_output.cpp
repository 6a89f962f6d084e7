#include "mocap/io/weight_output.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/io/gltf_writer.h"
#include "mocap/io/live_link_face_csv.h"
#include "mocap/io/live_link_face_map.h"
#include "mocap/io/shipped_retarget_maps.h"
#include "mocap/io/weights_csv_writer.h"

namespace mocap {

namespace {

/// The map in memory, else --map's map when given.
std::optional<RetargetMap> mapArgument(const WeightOutput& options)
{
  if (options.loadedMap)
    return options.loadedMap;
  return options.map ? std::optional<RetargetMap>(readRetargetMapByNameOrPath(*options.map)) : std::nullopt;
}

void writeLiveLink(const std::filesystem::path& out, const BlendshapeRig& rig,
                   const Eigen::Ref<const Eigen::MatrixXd>& weights, const WeightOutput& options)
{
  writeLiveLinkFaceCsv(out, liveLinkFaceRecordingOfRig(rig.shapeNames(), weights, mapArgument(options),
                                                       options.frameRate, options.headRotation));
}

std::optional<KeyCount> writeMapped(const std::filesystem::path& out, const std::string& extension,
                                    const BlendshapeRig& rig, const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                    const WeightOutput& options)
{
  const bool reduce = options.reduce && weights.rows() > 0;
  KeyCount count;
  if (extension == "csv") {
    writeWeightsCsv(out, rig.shapeNames(), weights, options.firstFrame, options.frameRate);
    return std::nullopt;
  }
  if (extension == "glb") {
    std::vector<Eigen::Index> keys;  // empty: every frame
    if (reduce) {
      KeyReduction shared = reduceFrameKeys(weights, *options.reduce);
      count.add(weights.rows(), static_cast<Eigen::Index>(shared.keys.size()), shared.maxError);
      keys = std::move(shared.keys);
    }
    writeRigGlb(out, rig, weights, options.frameRate, keys, options.startSeconds);
  } else if (extension == "fbx") {
    FbxRigOptions fbx = options.fbx;
    fbx.startSeconds = options.startSeconds.value_or(0.0);
    if (reduce)
      fbx.keys = {options.reduce, &count};
    writeRigFbx(out, rig, weights, options.frameRate, fbx);
  } else {
    throw InvalidArgument("weights are written to .csv, .glb or .fbx, not '" + out.string() + "'");
  }
  return reduce ? std::optional<KeyCount>(count) : std::nullopt;
}

} // namespace

std::optional<KeyCount> writeWeightOutput(const std::filesystem::path& out, const BlendshapeRig& rig,
                                          const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                          const WeightOutput& options)
{
  const std::string extension = lowerExtension(out);
  if (extension == "csv" && options.liveLink) {
    writeLiveLink(out, rig, weights, options);
    return std::nullopt;
  }
  const std::optional<RetargetMap> map = mapArgument(options);
  if (!map)
    return writeMapped(out, extension, rig, weights, options);
  const MappedWeights mapped = applyRetargetMap(*map, rig.shapeNames(), weights);
  return writeMapped(out, extension, retargetedRig(*map, rig), mapped.weights, options);
}

void checkWeightOutput(const BlendshapeRig& rig, const WeightOutput& options)
{
  const Eigen::MatrixXd noFrames(0, rig.shapeCount());
  if (options.liveLink)
    (void)applyRetargetMap(liveLinkFaceMap(rig.shapeNames(), mapArgument(options)), rig.shapeNames(), noFrames);
  else if (const std::optional<RetargetMap> map = mapArgument(options))
    (void)applyRetargetMap(*map, rig.shapeNames(), noFrames);
}

} // namespace mocap
