#include "mocap/deform/actor_profile_io.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_reader.h"
#include "mocap/base/json_writer.h"

#include <cmath>
#include <limits>
#include <optional>
#include <set>

namespace mocap {

namespace {

constexpr const char* kFormat = "mocap actor profile";

class ProfileReader
{
public:
  explicit ProfileReader(std::string source) : m_source(std::move(source)) {}

  ActorProfile read(const JsonValue& root) const
  {
    if (!root.isObject())
      fail("not an actor profile (a JSON object)");
    keys(root, {"format", "version", "name", "units", "neutral", "range_of_motion", "shapes", "binding"}, "the profile");
    if (string(root, "format", "the profile") != kFormat)
      fail("not an actor profile (its \"format\" must be \"" + std::string(kFormat) + "\")");
    if (number(root, "version", "the profile") != 1.0)
      fail("\"version\": 1 is the one this build reads");
    ActorProfile profile;
    profile.name = string(root, "name", "the profile");
    const std::optional<LengthUnit> units = parseLengthUnit(string(root, "units", "the profile"));
    if (!units)
      fail("\"units\" must be mm, cm or m");
    profile.units = *units;
    readNeutral(member(root, "neutral", "the profile"), profile);
    if (const JsonValue* rom = root.find("range_of_motion", "the profile"); rom && !rom->isNull()) {
      if (!rom->isString())
        fail("\"range_of_motion\" must be a take's name or null");
      profile.romSource = rom->string("range_of_motion");
    }
    readShapes(member(root, "shapes", "the profile"), profile);
    const JsonValue& binding = member(root, "binding", "the profile");
    if (!binding.isObject())
      fail("\"binding\" must be an object");
    const double vertices = number(binding, "mesh_vertices", "\"binding\"");
    if (!(vertices >= 1.0 && vertices == std::floor(vertices) && vertices < 1e12))
      fail("\"binding\": \"mesh_vertices\" must be a positive whole number");
    profile.binding = bindingFromJson(binding, m_source + " (binding)", static_cast<Eigen::Index>(vertices));
    return profile;
  }

private:
  void readNeutral(const JsonValue& neutral, ActorProfile& profile) const
  {
    if (!neutral.isObject())
      fail("\"neutral\" must be an object");
    keys(neutral, {"source", "markers"}, "\"neutral\"");
    profile.neutralSource = string(neutral, "source", "\"neutral\"");
    const JsonValue& markers = member(neutral, "markers", "\"neutral\"");
    if (!markers.isArray())
      fail("\"neutral\": \"markers\" must be an array");
    const std::vector<JsonValue>& list = markers.array("markers");
    profile.neutral.resize(static_cast<Eigen::Index>(list.size()), 3);
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string what = "\"neutral\" marker " + std::to_string(i + 1);
      if (!list[i].isObject())
        fail(what + " is not an object");
      keys(list[i], {"label", "position"}, what);
      profile.labels.push_back(string(list[i], "label", what));
      const JsonValue& position = member(list[i], "position", what);
      if (!position.isArray() || position.array(what).size() != 3)
        fail(what + ": \"position\" must be [x, y, z]");
      for (std::size_t c = 0; c < 3; ++c) {
        const JsonValue& value = position.array(what)[c];
        if (!value.isNumber())
          fail(what + ": \"position\" must be [x, y, z] numbers");
        profile.neutral(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(c)) = value.number(what);
      }
    }
  }

  void readShapes(const JsonValue& shapes, ActorProfile& profile) const
  {
    if (!shapes.isArray())
      fail("\"shapes\" must be an array");
    const std::vector<JsonValue>& list = shapes.array("shapes");
    profile.extent.resize(static_cast<Eigen::Index>(list.size()));
    profile.romMaximum.resize(static_cast<Eigen::Index>(list.size()));
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string what = "shape " + std::to_string(i + 1);
      if (!list[i].isObject())
        fail(what + " is not an object");
      keys(list[i], {"name", "extent", "rom_max"}, what);
      profile.shapes.push_back(string(list[i], "name", what));
      profile.extent(static_cast<Eigen::Index>(i)) = number(list[i], "extent", what);
      const JsonValue* maximum = list[i].find("rom_max", what);
      if (maximum && !maximum->isNull() && !maximum->isNumber())
        fail(what + ": \"rom_max\" must be a number or null");
      profile.romMaximum(static_cast<Eigen::Index>(i)) = maximum && maximum->isNumber()
                                                             ? maximum->number("rom_max")
                                                             : std::numeric_limits<double>::quiet_NaN();
    }
  }

  const JsonValue& member(const JsonValue& object, const char* key, const std::string& what) const
  {
    const JsonValue* value = object.find(key, what);
    if (!value)
      fail(what + " needs the key \"" + key + "\"");
    return *value;
  }

  std::string string(const JsonValue& object, const char* key, const std::string& what) const
  {
    const JsonValue& value = member(object, key, what);
    if (!value.isString())
      fail(what + ": \"" + key + "\" must be a string");
    return value.string(key);
  }

  double number(const JsonValue& object, const char* key, const std::string& what) const
  {
    const JsonValue& value = member(object, key, what);
    if (!value.isNumber())
      fail(what + ": \"" + key + "\" must be a number");
    return value.number(key);
  }

  void keys(const JsonValue& object, const std::set<std::string>& allowed, const std::string& what) const
  {
    for (const auto& [key, value] : object.object(what))
      if (allowed.count(key) == 0)
        fail(what + " has the key \"" + key + "\", which an actor profile does not have");
  }

  [[noreturn]] void fail(const std::string& message) const { throw FormatError(m_source, message); }

  std::string m_source;
};

} // namespace

ActorProfile parseActorProfile(std::string_view text, const std::string& sourceName)
{
  ActorProfile profile = ProfileReader(sourceName).read(parseJson(text, sourceName));
  try {
    checkActorProfile(profile);
  } catch (const InvalidArgument& error) {
    throw FormatError(sourceName, error.what());
  }
  return profile;
}

ActorProfile readActorProfile(const std::filesystem::path& path)
{
  return parseActorProfile(readFileBytes(path), path.string());
}

std::string actorProfileJson(const ActorProfile& profile)
{
  checkActorProfile(profile);
  JsonWriter json;
  json.beginObject();
  json.key("format").value(kFormat);
  json.key("version").value(1);
  json.key("name").value(profile.name);
  json.key("units").value(unitName(profile.units));
  json.key("neutral").beginObject();
  json.key("source").value(profile.neutralSource);
  json.key("markers").beginArray();
  for (std::size_t m = 0; m < profile.labels.size(); ++m) {
    json.beginObject();
    json.key("label").value(profile.labels[m]);
    json.key("position").beginArray();
    for (int c = 0; c < 3; ++c)
      json.value(profile.neutral(static_cast<Eigen::Index>(m), c));
    json.endArray();
    json.endObject();
  }
  json.endArray();
  json.endObject();
  json.key("range_of_motion");
  if (profile.romSource.empty())
    json.null();
  else
    json.value(profile.romSource);
  json.key("shapes").beginArray();
  for (std::size_t s = 0; s < profile.shapes.size(); ++s) {
    json.beginObject();
    json.key("name").value(profile.shapes[s]);
    json.key("extent").value(profile.extent(static_cast<Eigen::Index>(s)));
    json.key("rom_max").value(profile.romMaximum(static_cast<Eigen::Index>(s)));  // NaN is written as null
    json.endObject();
  }
  json.endArray();
  json.key("binding");
  writeBinding(json, profile.binding);
  json.endObject();
  return json.str() + "\n";
}

void writeActorProfile(const std::filesystem::path& path, const ActorProfile& profile)
{
  writeFileAtomically(path, actorProfileJson(profile));
}

} // namespace mocap
