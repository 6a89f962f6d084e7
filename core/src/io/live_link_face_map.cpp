#include "mocap/io/live_link_face_map.h"

#include "mocap/base/error.h"
#include "mocap/io/live_link_face_csv.h"
#include "mocap/io/shipped_retarget_maps.h"

#include <algorithm>
#include <cctype>
#include <set>

namespace mocap {

namespace {

bool isLiveLinkFaceCurve(const std::string& name)
{
  const std::vector<std::string>& curves = liveLinkFaceShapeNames();
  return std::find(curves.begin(), curves.end(), name) != curves.end();
}

std::string withInitial(std::string name, bool upper)
{
  if (!name.empty())
    name[0] = static_cast<char>(upper ? std::toupper(static_cast<unsigned char>(name[0]))
                                      : std::tolower(static_cast<unsigned char>(name[0])));
  return name;
}

bool allLiveLinkFaceCurves(const std::vector<std::string>& names)
{
  return std::all_of(names.begin(), names.end(), isLiveLinkFaceCurve);
}

RetargetMap shipped(const char* name)
{
  std::optional<RetargetMap> map = shippedRetargetMap(name);
  if (!map)
    throw InvalidArgument(std::string("the shipped retarget map '") + name + "' is missing from this build");
  return *std::move(map);
}

/// Throws naming the rig's shapes outside `placed`.
void requireAllPlaced(const std::vector<std::string>& rigShapes, const std::set<std::string>& placed,
                      const std::string& what)
{
  std::string missing;
  for (const std::string& shape : rigShapes)
    if (placed.count(shape) == 0)
      missing += (missing.empty() ? "'" : ", '") + shape + "'";
  if (!missing.empty())
    throw InvalidArgument("Live Link Face: " + what + missing +
                          " (neither ICT FaceKit's nor ARKit's names); give a retarget map (--map MAP.json)");
}

} // namespace

RetargetMap liveLinkFaceMapForRig(const std::vector<std::string>& rigShapes)
{
  if (allLiveLinkFaceCurves(rigShapes))
    return identityRetargetMap(rigShapes);
  const std::set<std::string> rig(rigShapes.begin(), rigShapes.end());
  std::set<std::string> placed;
  RetargetMap map = shipped("ict_to_arkit");
  for (RetargetChannel& channel : map.channels) {
    std::vector<RetargetSource> kept;
    for (const RetargetSource& source : channel.sources)
      if (rig.count(source.shape) > 0)
        kept.push_back(source);
    if (kept.empty() && rig.count(withInitial(channel.name, false)) > 0)
      kept.push_back({withInitial(channel.name, false), 1.0});
    for (const RetargetSource& source : kept)
      placed.insert(source.shape);
    channel.sources = std::move(kept);
  }
  requireAllPlaced(rigShapes, placed, "no curve takes the rig's shapes ");
  return map;
}

RetargetMap rigMapFromLiveLinkFace(const std::vector<std::string>& rigShapes)
{
  if (allLiveLinkFaceCurves(rigShapes))
    return identityRetargetMap(rigShapes);
  const RetargetMap ict = shipped("arkit_to_ict");
  RetargetMap map;
  std::set<std::string> placed;
  for (const std::string& shape : rigShapes) {
    const auto channel = std::find_if(ict.channels.begin(), ict.channels.end(),
                                      [&](const RetargetChannel& c) { return c.name == shape; });
    if (channel != ict.channels.end()) {
      map.channels.push_back(*channel);
    } else if (isLiveLinkFaceCurve(withInitial(shape, true))) {
      RetargetChannel own;
      own.name = shape;
      own.sources.push_back({withInitial(shape, true), 1.0});
      map.channels.push_back(std::move(own));
    } else {
      continue;
    }
    placed.insert(shape);
  }
  requireAllPlaced(rigShapes, placed, "no curve feeds the rig's shapes ");
  return map;
}

void checkLiveLinkFaceChannels(const RetargetMap& map)
{
  for (const RetargetChannel& channel : map.channels)
    if (!isLiveLinkFaceCurve(channel.name))
      throw InvalidArgument("retarget map: " + describeChannel(channel) +
                            " is not one of Live Link Face's 52 curves (JawOpen, MouthSmileLeft, …)");
}

void checkLiveLinkFaceSources(const RetargetMap& map)
{
  for (const RetargetChannel& channel : map.channels)
    for (const RetargetSource& source : channel.sources)
      if (!isLiveLinkFaceCurve(source.shape))
        throw InvalidArgument("retarget map: " + describeChannel(channel) + " takes '" + source.shape +
                              "', which is not one of Live Link Face's 52 curves");
}

RetargetMap liveLinkFaceMap(const std::vector<std::string>& rigShapes, const std::optional<RetargetMap>& map)
{
  RetargetMap checked = map ? *map : liveLinkFaceMapForRig(rigShapes);
  checkLiveLinkFaceChannels(checked);
  return checked;
}

LiveLinkFaceRecording liveLinkFaceRecordingOfRig(const std::vector<std::string>& rigShapes,
                                                 const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                                 const std::optional<RetargetMap>& map, double frameRate,
                                                 const Eigen::Ref<const Eigen::MatrixXd>& headRotation)
{
  const MappedWeights mapped = applyRetargetMap(liveLinkFaceMap(rigShapes, map), rigShapes, weights);
  return liveLinkFaceRecording(mapped.names, mapped.weights, frameRate, headRotation);
}

Eigen::MatrixXd liveLinkFaceWeightsOnRig(const Eigen::Ref<const Eigen::MatrixXd>& curves,
                                         const std::vector<std::string>& rigShapes,
                                         const std::optional<RetargetMap>& map)
{
  const RetargetMap used = map ? *map : rigMapFromLiveLinkFace(rigShapes);
  checkLiveLinkFaceSources(used);
  const MappedWeights mapped = applyRetargetMap(used, liveLinkFaceShapeNames(), curves);
  return mappedWeightsOnRig(used, mapped, rigShapes);
}

} // namespace mocap
