#pragma once

#include "mocap/model/blendshape_rig.h"

#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

namespace mocap {

/// One source of a target channel: a solved shape's weight times a gain.
struct RetargetSource
{
  std::string shape;
  double gain = 1.0;
};

/// One channel of the target rig: offset + Σ gain · source weight, clamped to [min, max].
struct RetargetChannel
{
  std::string name;
  std::vector<RetargetSource> sources;  // none: the channel holds `offset` (clamped)
  double offset = 0.0;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  int line = 0;  // where the channel starts in the map's file (0: not read from a file)
};

/// How our weight names map onto a target rig's channels (MetaHuman's ARKit curves, a studio's
/// own controls): per target channel, sources with gains, an offset and a clamp. Read and written
/// as JSON by io/retarget_map_io.h.
struct RetargetMap
{
  std::vector<RetargetChannel> channels;
};

/// Weights under their channel names, in the map's channel order.
struct MappedWeights
{
  std::vector<std::string> names;
  Eigen::MatrixXd weights;  // #frames × #channels
};

/// Checks the map on its own: channel names present and unique, finite gains and offset, a clamp
/// with min ≤ max (NaN refused), sources naming a shape. Throws InvalidArgument naming the
/// channel and its line in the file when it has one.
void checkRetargetMap(const RetargetMap& map);

/// The map's channels from `weights` (#frames × #shapes, a column per name in `shapeNames`).
/// Throws InvalidArgument (naming the channel and its line) when a source names a shape the
/// weights lack, or as checkRetargetMap. O(#frames · Σ #sources + #shapes).
[[nodiscard]] MappedWeights applyRetargetMap(const RetargetMap& map, const std::vector<std::string>& shapeNames,
                                             const Eigen::Ref<const Eigen::MatrixXd>& weights);

/// Each shape to a channel of its own name with gain 1, no offset and no clamp: the template a
/// user edits into their rig's map.
[[nodiscard]] RetargetMap identityRetargetMap(const std::vector<std::string>& shapeNames);

/// Mapped weights as a rig's columns (#frames × #rig shapes, in the rig's order): a channel must
/// name one of the rig's shapes (else InvalidArgument naming the channel and its line); a shape no
/// channel names stays 0. O(#frames · #shapes + #channels · #shapes).
[[nodiscard]] Eigen::MatrixXd mappedWeightsOnRig(const RetargetMap& map, const MappedWeights& mapped,
                                                 const std::vector<std::string>& rigShapes);

/// The rig re-expressed under the map's channels, for files that carry geometry with the curves
/// (glTF, FBX): one shape per channel, named as it, whose delta is Σ gain · the source's delta
/// (a channel without sources moves nothing). With the mapped weights it poses as the rig does
/// where no offset or clamp applies. Throws as applyRetargetMap for a source the rig lacks.
/// O(Σ over channels of the sources' moved vertices · log).
[[nodiscard]] BlendshapeRig retargetedRig(const RetargetMap& map, const BlendshapeRig& rig);

/// "channel 'Name' (line 12)", or without the line when the channel was not read from a file.
[[nodiscard]] std::string describeChannel(const RetargetChannel& channel);

} // namespace mocap
