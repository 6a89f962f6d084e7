#pragma once

#include "mocap/io/fbx_writer.h"
#include "mocap/math/key_reduction.h"
#include "mocap/model/blendshape_rig.h"
#include "mocap/model/retarget_map.h"

#include <Eigen/Core>

#include <filesystem>
#include <optional>
#include <string>

namespace mocap {

/// How solved (or read) weight curves are written: `mocap solve`, `mocap convert` and the
/// studio's Export Rig all write through writeWeightOutput, so each gets the same map and key
/// reduction.
struct WeightOutput
{
  std::optional<std::string> map;     ///< a shipped map's name or a map file (readRetargetMapByNameOrPath)
  /// A map already in memory (the studio's Retarget section, its gains edited), used instead of `map`.
  std::optional<RetargetMap> loadedMap;
  bool liveLink = false;              ///< .csv in Live Link Face's layout (else Frame,Time,<shape>,…)
  long long firstFrame = 0;           ///< the plain CSV's first frame number
  double frameRate = 0.0;
  FbxRigOptions fbx;                  ///< .fbx: axes and units (its startSeconds is set from startSeconds)
  /// A recording's start time (its first timecode): .fbx's first key and time span, .glb's
  /// animation extras.startSeconds. None: a solve, starting at 0.
  std::optional<double> startSeconds;
  /// --reduce: .glb keeps the fewest key frames all curves share, .fbx each curve's fewest keys,
  /// within this many weight units of every frame of the curves written (after the map).
  std::optional<double> reduce;
  Eigen::MatrixXd headRotation;       ///< Live Link: #frames × 3 head yaw, pitch, roll (× 9: then the eyes'), or empty for zeros
};

/// Writes `weights` (#frames × the rig's shapes) to `out` by its extension: weight curves (.csv,
/// plain or Live Link Face), or the rig with its animated weights (.glb, .fbx), each through the
/// map when one is given (the Live Link CSV through liveLinkFaceMapForRig when not). Every check
/// runs before the file is written, and the write is atomic. Returns the keys kept when
/// options.reduce applied (.glb, .fbx). Throws InvalidArgument naming the map's channel and line
/// or another extension, and IoError. O(#frames · #shapes + the file's size).
std::optional<KeyCount> writeWeightOutput(const std::filesystem::path& out, const BlendshapeRig& rig,
                                          const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                          const WeightOutput& options);

/// The checks writeWeightOutput makes of the map against the rig (a shape the rig lacks, a curve
/// Live Link Face does not have, a rig whose names need a map), made before a solve so they cost
/// none. Throws as writeWeightOutput. O(the map's size + #shapes).
void checkWeightOutput(const BlendshapeRig& rig, const WeightOutput& options);

} // namespace mocap
