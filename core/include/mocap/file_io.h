#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace mocap {

/// The whole file in one read. Throws IoError naming the file when it cannot be read.
[[nodiscard]] std::string readFileBytes(const std::filesystem::path& path);

/// Writes `bytes` to a temporary file beside `path`, flushes it and renames it over `path`,
/// so `path` is either the old file or the complete new one, never a partial write.
/// Throws IoError (and removes the temporary file) when any step fails.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

/// Lower-case extension without the dot ("c3d" for "take.C3D").
[[nodiscard]] std::string lowerExtension(const std::filesystem::path& path);

} // namespace mocap
