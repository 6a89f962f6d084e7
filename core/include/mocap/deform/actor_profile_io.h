#pragma once

#include "mocap/deform/actor_profile.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace mocap {

/// An actor profile as JSON:
///   {"format": "mocap actor profile", "version": 1, "name": …, "units": "mm",
///    "neutral": {"source": …, "markers": [{"label": …, "position": [x, y, z]}, …]},
///    "range_of_motion": TAKE or null,
///    "shapes": [{"name": …, "extent": …, "rom_max": … or null}, …],
///    "binding": the binding's JSON (mesh_binding.h, with "mesh_vertices")}
/// Throws FormatError naming the key for malformed JSON, another format or version, a missing
/// key, a key the format does not have or a value of the wrong type, then as checkActorProfile.
/// O(text size).
[[nodiscard]] ActorProfile parseActorProfile(std::string_view text, const std::string& sourceName);
/// parseActorProfile of a file; IoError when it cannot be read.
[[nodiscard]] ActorProfile readActorProfile(const std::filesystem::path& path);

/// The profile as that JSON.
[[nodiscard]] std::string actorProfileJson(const ActorProfile& profile);
/// Writes actorProfileJson atomically (the previous file is kept on failure). Throws IoError.
void writeActorProfile(const std::filesystem::path& path, const ActorProfile& profile);

} // namespace mocap
