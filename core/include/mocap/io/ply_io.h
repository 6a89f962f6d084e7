#pragma once

#include "mocap/model/mesh.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace mocap {

/// Reads a PLY mesh (ascii or binary_little_endian): the x, y, z properties of `vertex` (any
/// scalar type; other properties skipped) and the index list of `face` (`vertex_indices` or
/// `vertex_index`). Other elements are skipped. Throws IoError when the file cannot be read and
/// FormatError for a malformed header or body, a big-endian file, an index out of range or a
/// face with fewer than 3 corners. O(file size).
[[nodiscard]] Mesh readPly(const std::filesystem::path& path);
/// Parses PLY bytes as readPly does; `sourceName` names them in errors.
[[nodiscard]] Mesh parsePly(std::string_view bytes, const std::string& sourceName);

/// Binary little-endian PLY bytes of `mesh`'s faces with `vertices` as double x, y, z (exact).
/// UVs and normals are not written. Throws InvalidArgument when the vertex count differs.
/// O(#vertices + #corners).
[[nodiscard]] std::string plyBytes(const Mesh& mesh, const Eigen::Ref<const MeshVertices>& vertices);

/// Writes plyBytes atomically. Throws as plyBytes and IoError.
void writePly(const std::filesystem::path& path, const Mesh& mesh, const Eigen::Ref<const MeshVertices>& vertices);

} // namespace mocap
