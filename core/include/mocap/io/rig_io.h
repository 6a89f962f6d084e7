#pragma once

#include "mocap/model/blendshape_rig.h"

#include <filesystem>
#include <string>
#include <vector>

namespace mocap {

/// Reads a blendshape rig by the neutral's extension: a glTF 2.0 file (.glb, .gltf) holds the
/// neutral and its morph targets itself (`shapeFolder` must then be empty); an .obj/.ply neutral
/// takes its shapes from `shapeFolder` (readObjRig). `only`: just these shapes, in this order
/// (all when empty). Throws InvalidArgument for a folder given with a glTF rig or missing for an
/// OBJ/PLY one, and whatever the reader throws.
[[nodiscard]] BlendshapeRig readRig(const std::filesystem::path& neutral, const std::filesystem::path& shapeFolder,
                                    const std::vector<std::string>& only = {});

/// True for a path whose extension names a glTF file (.glb, .gltf). O(length).
[[nodiscard]] bool isGltfPath(const std::filesystem::path& path);

} // namespace mocap
