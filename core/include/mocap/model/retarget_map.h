#pragma once

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

/// "channel 'Name' (line 12)", or without the line when the channel was not read from a file.
[[nodiscard]] std::string describeChannel(const RetargetChannel& channel);

} // namespace mocap
