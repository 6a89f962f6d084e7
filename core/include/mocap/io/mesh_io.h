#pragma once

#include "mocap/model/mesh.h"

#include <filesystem>

namespace mocap {

/// Reads an .obj or .ply mesh by extension (obj_io.h, ply_io.h). Throws InvalidArgument for
/// another extension and whatever the reader throws.
[[nodiscard]] Mesh readMesh(const std::filesystem::path& path);

} // namespace mocap
