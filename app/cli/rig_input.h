#pragma once

#include "mocap/model/blendshape_rig.h"

#include <optional>
#include <string>

namespace mocap::cli {

/// Reads the rig of `--mesh`, `--shapes` and `--only` (readRig): a glTF rig holds its shapes, an
/// OBJ/PLY neutral needs the folder. Throws UsageError for a folder missing or given in vain, and
/// whatever readRig throws. O(the files' size).
[[nodiscard]] BlendshapeRig readInputRig(const std::string& mesh, const std::string& shapes,
                                         const std::optional<std::string>& only);

} // namespace mocap::cli
