#pragma once

#include "mocap/model/retarget_map.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

namespace detail {
/// One shipped retarget map as compiled in: its name (the file's stem) and its JSON.
struct ShippedMapText
{
  std::string_view name;
  std::string_view json;
};
/// The maps of resources/retarget, embedded at build time (the generated shipped_retarget_map_texts.cpp).
[[nodiscard]] const std::vector<ShippedMapText>& shippedRetargetMapTexts();
} // namespace detail

/// The retarget maps shipped in resources/retarget and compiled into the library: ict_to_arkit
/// (ICT FaceKit's shapes onto Live Link Face's 52 ARKit curves), arkit_to_ict (the way back: a
/// recording's curves onto the bundled ICT rig, each split shape from its one ARKit curve) and
/// ict_identity (the bundled rig's identity map, a template to edit). O(1).
[[nodiscard]] std::vector<std::string> shippedRetargetMapNames();

/// The shipped map called `name`, parsed (errors name "NAME (shipped)" and the line), or nullopt
/// when no shipped map has that name. O(the map's size).
[[nodiscard]] std::optional<RetargetMap> shippedRetargetMap(std::string_view name);

/// `--map`'s argument: a shipped map by name, else a map file. Throws IoError for a file that
/// cannot be read (saying which names are shipped when the argument has no .json extension) and
/// as parseRetargetMap. O(the map's size).
[[nodiscard]] RetargetMap readRetargetMapByNameOrPath(const std::string& nameOrPath);

} // namespace mocap
