#include "mocap/model/retarget_map.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

namespace mocap {

std::string describeChannel(const RetargetChannel& channel)
{
  std::string text = "channel '" + channel.name + "'";
  if (channel.line > 0)
    text += " (line " + std::to_string(channel.line) + ")";
  return text;
}

namespace {

/// "retarget map: channel 'X' (line N) takes 'S', a shape the rig does not have".
InvalidArgument missingSource(const RetargetChannel& channel, const RetargetSource& source)
{
  return InvalidArgument("retarget map: " + describeChannel(channel) + " takes '" + source.shape +
                         "', a shape the rig does not have");
}

} // namespace

void checkRetargetMap(const RetargetMap& map)
{
  std::set<std::string> seen;
  for (const RetargetChannel& channel : map.channels) {
    const std::string where = "retarget map: " + describeChannel(channel);
    if (channel.name.empty())
      throw InvalidArgument("retarget map: a channel has no name" +
                            (channel.line > 0 ? " (line " + std::to_string(channel.line) + ")" : std::string()));
    if (!seen.insert(channel.name).second)
      throw InvalidArgument(where + " is named twice");
    if (!std::isfinite(channel.offset))
      throw InvalidArgument(where + ": the offset is not finite");
    if (std::isnan(channel.min) || std::isnan(channel.max) || channel.min > channel.max)
      throw InvalidArgument(where + ": the clamp needs min ≤ max (min " + std::to_string(channel.min) + ", max " +
                            std::to_string(channel.max) + ")");
    for (const RetargetSource& source : channel.sources) {
      if (source.shape.empty())
        throw InvalidArgument(where + ": a source names no shape");
      if (!std::isfinite(source.gain))
        throw InvalidArgument(where + ": the gain of '" + source.shape + "' is not finite");
    }
  }
}

MappedWeights applyRetargetMap(const RetargetMap& map, const std::vector<std::string>& shapeNames,
                               const Eigen::Ref<const Eigen::MatrixXd>& weights)
{
  checkRetargetMap(map);
  if (weights.cols() != static_cast<Eigen::Index>(shapeNames.size()))
    throw InvalidArgument("retarget map: " + std::to_string(weights.cols()) + " weight columns for " +
                          std::to_string(shapeNames.size()) + " shape names");
  std::unordered_map<std::string, Eigen::Index> column;
  for (std::size_t s = 0; s < shapeNames.size(); ++s)
    column.emplace(shapeNames[s], static_cast<Eigen::Index>(s));
  MappedWeights mapped;
  mapped.weights.resize(weights.rows(), static_cast<Eigen::Index>(map.channels.size()));
  for (std::size_t c = 0; c < map.channels.size(); ++c) {
    const RetargetChannel& channel = map.channels[c];
    auto out = mapped.weights.col(static_cast<Eigen::Index>(c));
    out.setConstant(channel.offset);
    for (const RetargetSource& source : channel.sources) {
      const auto found = column.find(source.shape);
      if (found == column.end())
        throw missingSource(channel, source);
      out += source.gain * weights.col(found->second);
    }
    out = out.cwiseMax(channel.min).cwiseMin(channel.max);
    mapped.names.push_back(channel.name);
  }
  return mapped;
}

Eigen::MatrixXd mappedWeightsOnRig(const RetargetMap& map, const MappedWeights& mapped,
                                   const std::vector<std::string>& rigShapes)
{
  Eigen::MatrixXd weights = Eigen::MatrixXd::Zero(mapped.weights.rows(), static_cast<Eigen::Index>(rigShapes.size()));
  for (std::size_t c = 0; c < mapped.names.size(); ++c) {
    const auto found = std::find(rigShapes.begin(), rigShapes.end(), mapped.names[c]);
    if (found == rigShapes.end()) {
      const RetargetChannel* channel = c < map.channels.size() ? &map.channels[c] : nullptr;
      throw InvalidArgument("retarget map: " +
                            (channel ? describeChannel(*channel) : "channel '" + mapped.names[c] + "'") +
                            " is not a shape of the rig");
    }
    weights.col(found - rigShapes.begin()) = mapped.weights.col(static_cast<Eigen::Index>(c));
  }
  return weights;
}

BlendshapeRig retargetedRig(const RetargetMap& map, const BlendshapeRig& rig)
{
  checkRetargetMap(map);
  BlendshapeRig out;
  out.neutral = rig.neutral;
  for (const RetargetChannel& channel : map.channels) {
    std::map<Eigen::Index, Eigen::Vector3d> delta;  // ascending vertices, as SparseShape keeps them
    for (const RetargetSource& source : channel.sources) {
      const std::optional<Eigen::Index> index = rig.shapeIndex(source.shape);
      if (!index)
        throw missingSource(channel, source);
      const SparseShape& shape = rig.shapes[static_cast<std::size_t>(*index)];
      for (Eigen::Index i = 0; i < shape.size(); ++i) {
        auto [entry, added] = delta.try_emplace(shape.vertices[static_cast<std::size_t>(i)], Eigen::Vector3d::Zero());
        (void)added;
        entry->second += source.gain * shape.deltas.row(i).transpose();
      }
    }
    SparseShape shape;
    shape.name = channel.name;
    shape.deltas.resize(static_cast<Eigen::Index>(delta.size()), 3);
    for (const auto& [vertex, d] : delta) {
      shape.deltas.row(shape.size()) = d.transpose();
      shape.vertices.push_back(vertex);
    }
    out.shapes.push_back(std::move(shape));
  }
  return out;
}

RetargetMap identityRetargetMap(const std::vector<std::string>& shapeNames)
{
  RetargetMap map;
  for (const std::string& name : shapeNames) {
    RetargetChannel channel;
    channel.name = name;
    channel.sources.push_back({name, 1.0});
    map.channels.push_back(std::move(channel));
  }
  return map;
}

} // namespace mocap
