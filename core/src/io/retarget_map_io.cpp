#include "mocap/io/retarget_map_io.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_reader.h"
#include "mocap/base/json_writer.h"

#include <algorithm>
#include <limits>
#include <regex>
#include <set>

namespace mocap {

namespace {

constexpr const char* kFormat = "mocap retarget map";

/// The line of each channel object: where each `"name":` key stands, in order. The format has
/// no other "name" key, so the n-th one opens the n-th channel.
std::vector<int> channelLines(std::string_view text)
{
  std::vector<int> lines;
  const std::regex nameKey(R"("name"\s*:)");
  const std::string copy(text);
  int line = 1;
  std::size_t counted = 0;
  for (auto it = std::sregex_iterator(copy.begin(), copy.end(), nameKey); it != std::sregex_iterator(); ++it) {
    const auto at = static_cast<std::size_t>(it->position());
    line += static_cast<int>(std::count(copy.begin() + static_cast<std::ptrdiff_t>(counted),
                                        copy.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    counted = at;
    lines.push_back(line);
  }
  return lines;
}

class MapReader
{
public:
  MapReader(std::string sourceName, std::vector<int> lines) : m_source(std::move(sourceName)), m_lines(std::move(lines))
  {
  }

  RetargetMap read(const JsonValue& root) const
  {
    checkKeys(root, {"format", "version", "channels"}, "the map", 0);
    const JsonValue* format = root.find("format", "the map");
    if (!format || !format->isString() || format->string("format") != kFormat)
      fail("not a retarget map (its \"format\" must be \"" + std::string(kFormat) + "\")", 0);
    const JsonValue* version = root.find("version", "the map");
    if (!version || !version->isNumber() || version->number("version") != 1.0)
      fail("version 1 is the one this build reads", 0);
    const JsonValue* channels = root.find("channels", "the map");
    if (!channels || !channels->isArray())
      fail("\"channels\" must be an array", 0);
    RetargetMap map;
    const std::vector<JsonValue>& list = channels->array("channels");
    for (std::size_t i = 0; i < list.size(); ++i)
      map.channels.push_back(channel(list[i], i < m_lines.size() ? m_lines[i] : 0, i));
    return map;
  }

private:
  RetargetChannel channel(const JsonValue& value, int line, std::size_t index) const
  {
    const std::string what = "channel " + std::to_string(index + 1);
    if (!value.isObject())
      fail(what + " is not an object", line);
    checkKeys(value, {"name", "sources", "offset", "min", "max"}, what, line);
    RetargetChannel channel;
    channel.line = line;
    const JsonValue* name = value.find("name", what);
    if (!name || !name->isString())
      fail(what + " needs a \"name\" string", line);
    channel.name = name->string(what);
    channel.offset = number(value, "offset", 0.0, what, line);
    channel.min = number(value, "min", -std::numeric_limits<double>::infinity(), what, line);
    channel.max = number(value, "max", std::numeric_limits<double>::infinity(), what, line);
    if (const JsonValue* sources = value.find("sources", what)) {
      if (!sources->isArray())
        fail(what + ": \"sources\" must be an array", line);
      for (const JsonValue& source : sources->array(what)) {
        if (!source.isObject())
          fail(what + ": a source is not an object", line);
        checkKeys(source, {"shape", "gain"}, what + "'s source", line);
        const JsonValue* shape = source.find("shape", what);
        if (!shape || !shape->isString())
          fail(what + ": a source needs a \"shape\" string", line);
        channel.sources.push_back({shape->string(what), number(source, "gain", 1.0, what, line)});
      }
    }
    return channel;
  }

  double number(const JsonValue& object, const char* key, double absent, const std::string& what, int line) const
  {
    const JsonValue* value = object.find(key, what);
    if (!value || value->isNull())
      return absent;
    if (!value->isNumber())
      fail(what + ": \"" + key + "\" must be a number", line);
    return value->number(key);
  }

  void checkKeys(const JsonValue& object, const std::set<std::string>& allowed, const std::string& what, int line) const
  {
    for (const auto& [key, value] : object.object(what))
      if (allowed.count(key) == 0)
        fail(what + " has the key \"" + key + "\", which a retarget map does not have", line);
  }

  [[noreturn]] void fail(const std::string& message, int line) const
  {
    throw FormatError(m_source, (line > 0 ? "line " + std::to_string(line) + ": " : std::string()) + message);
  }

  std::string m_source;
  std::vector<int> m_lines;
};

void writeNumberUnlessDefault(JsonWriter& json, const char* key, double value, double absent)
{
  if (value != absent)
    json.key(key).value(value);
}

} // namespace

RetargetMap parseRetargetMap(std::string_view text, const std::string& sourceName)
{
  const JsonValue root = parseJson(text, sourceName);
  if (!root.isObject())
    throw FormatError(sourceName, "not a retarget map (a JSON object)");
  RetargetMap map = MapReader(sourceName, channelLines(text)).read(root);
  checkRetargetMap(map);
  return map;
}

RetargetMap readRetargetMap(const std::filesystem::path& path)
{
  return parseRetargetMap(readFileBytes(path), path.string());
}

std::string retargetMapJson(const RetargetMap& map)
{
  JsonWriter json;
  json.beginObject();
  json.key("format").value(kFormat);
  json.key("version").value(1);
  json.key("channels").beginArray();
  for (const RetargetChannel& channel : map.channels) {
    json.beginObject();
    json.key("name").value(channel.name);
    json.key("sources").beginArray();
    for (const RetargetSource& source : channel.sources) {
      json.beginObject();
      json.key("shape").value(source.shape);
      json.key("gain").value(source.gain);
      json.endObject();
    }
    json.endArray();
    writeNumberUnlessDefault(json, "offset", channel.offset, 0.0);
    writeNumberUnlessDefault(json, "min", channel.min, -std::numeric_limits<double>::infinity());
    writeNumberUnlessDefault(json, "max", channel.max, std::numeric_limits<double>::infinity());
    json.endObject();
  }
  json.endArray();
  json.endObject();
  return json.str() + "\n";
}

void writeRetargetMap(const std::filesystem::path& path, const RetargetMap& map)
{
  writeFileAtomically(path, retargetMapJson(map));
}

} // namespace mocap
