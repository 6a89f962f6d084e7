#include "mocap/io/shipped_retarget_maps.h"

#include "mocap/base/error.h"
#include "mocap/io/retarget_map_io.h"

#include <filesystem>

namespace mocap {

std::vector<std::string> shippedRetargetMapNames()
{
  std::vector<std::string> names;
  for (const detail::ShippedMapText& map : detail::shippedRetargetMapTexts())
    names.emplace_back(map.name);
  return names;
}

std::optional<RetargetMap> shippedRetargetMap(std::string_view name)
{
  for (const detail::ShippedMapText& map : detail::shippedRetargetMapTexts())
    if (map.name == name)
      return parseRetargetMap(map.json, std::string(name) + " (shipped)");
  return std::nullopt;
}

RetargetMap readRetargetMapByNameOrPath(const std::string& nameOrPath)
{
  if (std::optional<RetargetMap> shipped = shippedRetargetMap(nameOrPath))
    return *std::move(shipped);
  std::error_code error;
  if (std::filesystem::path(nameOrPath).extension() != ".json" && !std::filesystem::exists(nameOrPath, error)) {
    std::string names;
    for (const std::string& name : shippedRetargetMapNames())
      names += (names.empty() ? "" : ", ") + name;
    throw IoError("retarget map '" + nameOrPath + "' is neither a shipped map (" + names + ") nor a file");
  }
  return readRetargetMap(nameOrPath);
}

} // namespace mocap
