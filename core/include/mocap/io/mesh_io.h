#pragma once

#include "mocap/model/mesh.h"

#include <filesystem>

namespace mocap {

/// Reads an .obj or .ply mesh by extension (obj_io.h, ply_io.h), or the neutral of a glTF rig
/// (.glb, .gltf: gltf_rig_reader.h, which needs a mesh with morph targets). Throws
/// InvalidArgument for another extension and whatever the reader throws. O(file size).
[[nodiscard]] Mesh readMesh(const std::filesystem::path& path);

} // namespace mocap
