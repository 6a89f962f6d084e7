#include "mocap/io/c3d_point_types.h"

#include "mocap/base/text.h"
#include "mocap/io/c3d_string_lists.h"

#include <algorithm>
#include <array>
#include <unordered_map>

namespace mocap {

namespace {

std::string defaultListName(PointType type)
{
  switch (type) {
  case PointType::Angle: return "ANGLES";
  case PointType::Force: return "FORCES";
  case PointType::Moment: return "MOMENTS";
  case PointType::Power: return "POWERS";
  case PointType::Virtual: return "VIRTUALS";
  case PointType::Marker:
  case PointType::Other: break;
  }
  return "OTHERS";
}

/// The types whose lists a reader finds without POINT:TYPE_GROUPS (Nexus's four).
constexpr std::array kListsWithoutTypeGroups{PointType::Angle, PointType::Force, PointType::Moment, PointType::Power};

bool isFoundWithoutTypeGroups(PointType type)
{
  return std::find(kListsWithoutTypeGroups.begin(), kListsWithoutTypeGroups.end(), type) !=
         kListsWithoutTypeGroups.end();
}

// A list name that is one of the POINT group's own parameters: a file naming it in TYPE_GROUPS
// would otherwise type every point or have its labels rewritten as a type list.
bool isPointGroupParameter(const std::string& name)
{
  const std::string upper = toUpper(name);
  for (const char* own : {"USED", "FRAMES", "SCALE", "RATE", "UNITS", "DATA_START", "TYPE_GROUPS"})
    if (upper == own)
      return true;
  return upper.rfind("LABELS", 0) == 0 || upper.rfind("DESCRIPTIONS", 0) == 0;
}

} // namespace

std::vector<std::pair<std::string, PointType>> c3dPointTypeLists(const C3dParameterTree& tree)
{
  std::vector<std::pair<std::string, PointType>> lists;
  const std::vector<std::string> groups = tree.strings("POINT", "TYPE_GROUPS");
  for (std::size_t i = 0; i + 1 < groups.size(); i += 2)
    if (!isPointGroupParameter(groups[i]))
      lists.emplace_back(groups[i], parsePointType(toLower(groups[i + 1])).value_or(PointType::Other));
  if (lists.empty())
    for (const PointType type : kListsWithoutTypeGroups)
      lists.emplace_back(defaultListName(type), type);
  return lists;
}

void readC3dPointTypes(const C3dParameterTree& tree, Take& take)
{
  std::unordered_map<std::string_view, Eigen::Index> index;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    index.emplace(take.label(m), m);
  for (const auto& [list, type] : c3dPointTypeLists(tree))
    for (const std::string& label : c3dStringsAcrossParts(tree, "POINT", list))
      if (const auto it = index.find(label); it != index.end())
        take.setPointType(it->second, type);
}

void writeC3dPointTypes(const Take& take, C3dParameterTree& tree)
{
  std::vector<std::pair<std::string, PointType>> lists = c3dPointTypeLists(tree);
  const bool hadTypeGroups = tree.find("POINT", "TYPE_GROUPS") != nullptr;
  // The list each label was in (the last one, as on reading a later list wins).
  std::unordered_map<std::string, std::size_t> listOf;
  for (std::size_t i = 0; i < lists.size(); ++i)
    for (const std::string& label : c3dStringsAcrossParts(tree, "POINT", lists[i].first))
      listOf[label] = i;
  std::vector<std::vector<std::string>> contents(lists.size());
  bool typeGroupsNeeded = false;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    const PointType type = take.pointType(m);
    if (type == PointType::Marker)
      continue;
    const auto was = listOf.find(take.label(m));
    std::size_t i = 0;
    if (was != listOf.end() && lists[was->second].second == type)
      i = was->second;
    else
      i = static_cast<std::size_t>(std::find_if(lists.begin(), lists.end(), [type](const auto& list) {
                                     return list.second == type;
                                   }) - lists.begin());
    if (i == lists.size()) {
      lists.emplace_back(defaultListName(type), type);
      contents.emplace_back();
      typeGroupsNeeded = typeGroupsNeeded || hadTypeGroups || !isFoundWithoutTypeGroups(type);
    }
    contents[i].push_back(take.label(m));
  }
  for (std::size_t i = 0; i < lists.size(); ++i)
    if (!contents[i].empty() || tree.find("POINT", lists[i].first))
      setC3dStringsAcrossParts(tree, "POINT", lists[i].first, contents[i]);
  if (!typeGroupsNeeded)
    return;
  std::vector<std::string> pairs;
  for (const auto& [list, type] : lists) {
    pairs.push_back(list);
    pairs.push_back(toUpper(pointTypeName(type)));
  }
  tree.set("POINT", C3dParameter::makeStrings("TYPE_GROUPS", pairs));
}

} // namespace mocap
