#pragma once

#include "mocap/model/blendshape_rig.h"

#include <filesystem>
#include <string>
#include <vector>

namespace mocap {

/// Reads a blendshape rig laid out as ICT FaceKit ships one: a neutral OBJ/PLY and a folder with
/// one OBJ per shape, named after it (`jawOpen.obj`). Shapes are kept in name order (or the order
/// of `only`, when given: just those), as sparse deltas from the neutral. Files other than *.obj
/// and the neutral itself are ignored. Nothing half-loaded: throws IoError for a folder that is
/// missing or has no shapes, IoError/FormatError for a file that cannot be read or parsed, and
/// InvalidArgument for a shape with a different vertex count, a non-finite coordinate or a name
/// in `only` without a file.
/// O(total file size); the files are parsed on all cores.
[[nodiscard]] BlendshapeRig readObjRig(const std::filesystem::path& neutral, const std::filesystem::path& shapeFolder,
                                       const std::vector<std::string>& only = {});

} // namespace mocap
