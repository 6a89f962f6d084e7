#pragma once

#include "mocap/model/take.h"

#include <string>

namespace mocap::cli {

/// Reads the take at `path` (format by extension) and prints each quirk the reader tolerated to
/// stderr as "PATH: warning: …", so no command reads a take silently. Throws as readTake.
[[nodiscard]] Take readInputTake(const std::string& path);

} // namespace mocap::cli
