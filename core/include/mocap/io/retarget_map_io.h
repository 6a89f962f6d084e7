#pragma once

#include "mocap/model/retarget_map.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace mocap {

/// A retarget map as JSON:
///   {"format": "mocap retarget map", "version": 1,
///    "channels": [{"name": "JawOpen", "sources": [{"shape": "jawOpen", "gain": 1.0}],
///                  "offset": 0.0, "min": 0.0, "max": 1.0}, …]}
/// "sources", "gain", "offset", "min" and "max" may be left out (none, 1, 0, no clamp; a null
/// min or max is no clamp on that side). Each channel remembers its line, so later errors (a
/// shape the rig lacks) name it too. Throws FormatError for malformed JSON, another format or
/// version, a key this format does not have (a misspelt "gian" would otherwise be ignored) or a
/// value of the wrong type, naming the line; then checks as checkRetargetMap. O(text size).
[[nodiscard]] RetargetMap parseRetargetMap(std::string_view text, const std::string& sourceName);
/// parseRetargetMap of a file; IoError when it cannot be read.
[[nodiscard]] RetargetMap readRetargetMap(const std::filesystem::path& path);

/// The map as that JSON, one channel per block, clamps written only where set.
[[nodiscard]] std::string retargetMapJson(const RetargetMap& map);
/// Writes retargetMapJson atomically. Throws IoError.
void writeRetargetMap(const std::filesystem::path& path, const RetargetMap& map);

} // namespace mocap
