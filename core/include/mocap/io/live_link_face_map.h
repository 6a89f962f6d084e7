#pragma once

#include "mocap/io/live_link_face_csv.h"
#include "mocap/model/retarget_map.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace mocap {

/// The map a rig's weights take to Live Link Face's 52 curves when none is given. A rig already
/// named as the app names its curves (JawOpen, MouthSmileLeft) maps by identity. Otherwise the
/// shipped ict_to_arkit map fitted to the rig: a source the rig lacks counts 0 (the rig has no
/// such shape to solve), and a curve left without a source takes the rig's shape named as the
/// curve with a lowercase initial (Apple's own ARKit names: browInnerUp, cheekPuff, tongueOut,
/// which ICT FaceKit splits or leaves out). Throws InvalidArgument naming the rig's shapes that no
/// curve takes (a rig named otherwise needs a map of its own). O(#shapes + the map's size).
[[nodiscard]] RetargetMap liveLinkFaceMapForRig(const std::vector<std::string>& rigShapes);

/// The way back, a recording's curves onto a rig when no map is given: identity for a rig named as
/// the app names its curves, else the shipped arkit_to_ict map's channels the rig has, and for a
/// rig shape without one, the curve named as the shape with an uppercase initial (browInnerUp ←
/// BrowInnerUp). Throws InvalidArgument naming the rig's shapes no curve feeds. O(#shapes + the
/// map's size).
[[nodiscard]] RetargetMap rigMapFromLiveLinkFace(const std::vector<std::string>& rigShapes);

/// Throws InvalidArgument naming the first channel (and its map line) that is not one of Live Link
/// Face's 52 curve names: a map written for its CSV must target those. O(#channels).
void checkLiveLinkFaceChannels(const RetargetMap& map);

/// Throws InvalidArgument naming the first channel (and its line) with a source that is not one of
/// Live Link Face's 52 curves: a map reading a recording takes only those. O(Σ #sources).
void checkLiveLinkFaceSources(const RetargetMap& map);

/// The map a rig's weights take onto the 52 curves: `map` when given, else liveLinkFaceMapForRig;
/// checked with checkLiveLinkFaceChannels. Throws as those. O(the map's size + #shapes).
[[nodiscard]] RetargetMap liveLinkFaceMap(const std::vector<std::string>& rigShapes,
                                          const std::optional<RetargetMap>& map);

/// A rig's solved weights (#frames × #rigShapes) as a Live Link Face recording through
/// liveLinkFaceMap(rigShapes, map), timed at `frameRate`, with `headRotation` as
/// liveLinkFaceRecording takes it: what the Live Link CSV writes and the live stream sends.
/// Throws as liveLinkFaceMap and applyRetargetMap. O(#frames · (Σ #sources + 61)).
[[nodiscard]] LiveLinkFaceRecording liveLinkFaceRecordingOfRig(const std::vector<std::string>& rigShapes,
                                                               const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                                               const std::optional<RetargetMap>& map, double frameRate,
                                                               const Eigen::Ref<const Eigen::MatrixXd>& headRotation);
/// A recording's curves (#rows × 52, in liveLinkFaceShapeNames() order) as weights of a rig
/// (#rows × #rig shapes, in the rig's order) through `map` (the 52 curves onto the rig's shapes)
/// or, when none, rigMapFromLiveLinkFace; a shape no channel names stays 0. What `mocap convert
/// REC.csv` and the studio's Open Live Link Recording both read. Throws InvalidArgument as
/// rigMapFromLiveLinkFace, checkLiveLinkFaceSources, applyRetargetMap and mappedWeightsOnRig (a
/// channel the rig lacks), naming the channel and its line. O(#rows · (Σ #sources + #shapes)).
[[nodiscard]] Eigen::MatrixXd liveLinkFaceWeightsOnRig(const Eigen::Ref<const Eigen::MatrixXd>& curves,
                                                       const std::vector<std::string>& rigShapes,
                                                       const std::optional<RetargetMap>& map);

} // namespace mocap
