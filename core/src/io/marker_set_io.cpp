#include "mocap/io/marker_set_io.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_reader.h"
#include "mocap/base/json_writer.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace mocap {

namespace {

constexpr const char* kFormat = "mocap-marker-set";

void writePairs(JsonWriter& json, const char* key, const MarkerSet& set, const std::vector<LabelPair>& pairs)
{
  json.key(key).beginArray();
  for (const LabelPair& pair : pairs)
    json.beginArray()
        .value(set.labels[static_cast<std::size_t>(pair.first)])
        .value(set.labels[static_cast<std::size_t>(pair.second)])
        .endArray();
  json.endArray();
}

std::vector<LabelPair> readPairs(const JsonValue& root, const std::string& key,
                                 const std::map<std::string, Eigen::Index>& indexOf)
{
  std::vector<LabelPair> pairs;
  const JsonValue* list = root.find(key, "the marker set");
  if (!list)
    return pairs;
  for (const JsonValue& item : list->array("\"" + key + "\"")) {
    const auto& two = item.array("each of \"" + key + "\"");
    if (two.size() != 2)
      throw InvalidArgument("each of \"" + key + "\" must name two labels");
    Eigen::Index index[2] = {0, 0};
    for (std::size_t k = 0; k < 2; ++k) {
      const std::string& label = two[k].string("a label in \"" + key + "\"");
      const auto it = indexOf.find(label);
      if (it == indexOf.end())
        throw InvalidArgument("\"" + key + "\" names unknown label '" + label + "'");
      index[k] = it->second;
    }
    pairs.emplace_back(index[0], index[1]);
  }
  return pairs;
}

MarkerSet markerSetFromJson(const JsonValue& root)
{
  const JsonValue* format = root.find("format", "the marker set");
  if (!format || format->string("\"format\"") != kFormat)
    throw InvalidArgument(std::string("\"format\" must be \"") + kFormat + "\"");
  const JsonValue* version = root.find("version", "the marker set");
  if (!version || version->number("\"version\"") != 1.0)
    throw InvalidArgument("\"version\" must be 1");
  MarkerSet set;
  if (const JsonValue* units = root.find("units", "the marker set")) {
    const auto unit = parseLengthUnit(units->string("\"units\""));
    if (!unit)
      throw InvalidArgument("\"units\" must be mm, cm or m");
    set.units = *unit;
  }
  const JsonValue* markers = root.find("markers", "the marker set");
  if (!markers)
    throw InvalidArgument("missing \"markers\"");
  const auto& list = markers->array("\"markers\"");
  set.neutral.resize(static_cast<Eigen::Index>(list.size()), 3);
  std::map<std::string, Eigen::Index> indexOf;
  bool anyVertex = false;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const JsonValue* label = list[i].find("label", "each marker");
    const JsonValue* position = list[i].find("position", "each marker");
    if (!label || !position)
      throw InvalidArgument("each marker needs \"label\" and \"position\"");
    set.labels.push_back(label->string("\"label\""));
    indexOf[set.labels.back()] = static_cast<Eigen::Index>(i);
    const auto& xyz = position->array("\"position\"");
    if (xyz.size() != 3)
      throw InvalidArgument("\"position\" of '" + set.labels.back() + "' must have three numbers");
    for (Eigen::Index k = 0; k < 3; ++k)
      set.neutral(static_cast<Eigen::Index>(i), k) = xyz[static_cast<std::size_t>(k)].number("a coordinate");
    const JsonValue* vertex = list[i].find("vertex", "each marker");
    anyVertex = anyVertex || vertex != nullptr;
    const double index = vertex ? vertex->number("\"vertex\"") : -1.0;
    if (index != std::floor(index) || index < -1.0 || index > 1e12)
      throw InvalidArgument("\"vertex\" must be an integer from -1 to 10^12");
    set.meshVertices.push_back(static_cast<Eigen::Index>(index));
  }
  if (!anyVertex)
    set.meshVertices.clear();
  set.pairs = readPairs(root, "pairs", indexOf);
  set.links = readPairs(root, "links", indexOf);
  if (const JsonValue* mesh = root.find("mesh", "the marker set"))
    set.meshFile = mesh->string("\"mesh\"");
  validateMarkerSet(set);
  return set;
}

} // namespace

std::string markerSetJson(const MarkerSet& set)
{
  validateMarkerSet(set);
  JsonWriter json;
  json.beginObject();
  json.key("format").value(kFormat);
  json.key("version").value(1);
  json.key("units").value(unitName(set.units));
  json.key("markers").beginArray();
  for (Eigen::Index i = 0; i < set.size(); ++i) {
    json.beginObject().key("label").value(set.labels[static_cast<std::size_t>(i)]);
    json.key("position").beginArray();
    for (Eigen::Index k = 0; k < 3; ++k)
      json.value(set.neutral(i, k));
    json.endArray();
    if (!set.meshVertices.empty() && set.meshVertices[static_cast<std::size_t>(i)] >= 0)
      json.key("vertex").value(static_cast<std::int64_t>(set.meshVertices[static_cast<std::size_t>(i)]));
    json.endObject();
  }
  json.endArray();
  writePairs(json, "pairs", set, set.pairs);
  writePairs(json, "links", set, set.links);
  if (!set.meshFile.empty())
    json.key("mesh").value(set.meshFile);
  json.endObject();
  return json.str() + "\n";
}

MarkerSet parseMarkerSet(std::string_view text, const std::string& sourceName)
{
  const JsonValue root = parseJson(text, sourceName);
  try {
    return markerSetFromJson(root);
  } catch (const InvalidArgument& e) {
    throw FormatError(sourceName, e.what());
  }
}

MarkerSet readMarkerSet(const std::filesystem::path& path)
{
  return parseMarkerSet(readFileBytes(path), path.string());
}

void writeMarkerSet(const MarkerSet& set, const std::filesystem::path& path)
{
  writeFileAtomically(path, markerSetJson(set));
}

MarkerSymmetry readMarkerPairs(const std::filesystem::path& path, const std::vector<std::string>& labels)
{
  if (lowerExtension(path) != "json")
    return parseMarkerPairs(readFileBytes(path), labels, path.string());
  // A marker-set file: its pairs by label, mapped onto `labels`.
  const MarkerSet set = readMarkerSet(path);
  const auto indexOf = [&](Eigen::Index i) {
    const std::string& label = set.labels[static_cast<std::size_t>(i)];
    const auto it = std::find(labels.begin(), labels.end(), label);
    if (it == labels.end())
      throw FormatError(path.string(), "pair label '" + label + "' is not a marker of the take");
    return static_cast<Eigen::Index>(it - labels.begin());
  };
  std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs;
  for (const LabelPair& pair : set.pairs)
    pairs.emplace_back(indexOf(pair.first), indexOf(pair.second));
  return MarkerSymmetry(static_cast<Eigen::Index>(labels.size()), pairs);
}

} // namespace mocap
