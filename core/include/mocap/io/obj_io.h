#pragma once

#include "mocap/model/mesh.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace mocap {

/// Reads a Wavefront OBJ: `v`, `vt`, `vn` and `f` lines (polygons of any size, `v`, `v/t`,
/// `v//n`, `v/t/n` corners, negative indices relative to the end). Other statements (groups,
/// materials, smoothing, comments) are skipped. Throws IoError when the file cannot be read and
/// FormatError ("FILE: line N: ...") for a malformed number or an index out of range, a face with
/// fewer than three corners or a repeated vertex. O(file size).
[[nodiscard]] Mesh readObj(const std::filesystem::path& path);
/// Parses OBJ text as readObj does; `sourceName` names it in errors.
[[nodiscard]] Mesh parseObj(std::string_view text, const std::string& sourceName);

/// The OBJ text of `mesh` with `vertices` (#vertices × 3) in place of mesh.vertices: the same
/// faces, UVs and normals, numbers in shortest round-trip form. Throws InvalidArgument when the
/// vertex count differs. O(#vertices + #corners).
[[nodiscard]] std::string objText(const Mesh& mesh, const Eigen::Ref<const MeshVertices>& vertices);

/// Writes objText atomically. Throws as objText and IoError.
void writeObj(const std::filesystem::path& path, const Mesh& mesh, const Eigen::Ref<const MeshVertices>& vertices);
inline void writeObj(const std::filesystem::path& path, const Mesh& mesh) { writeObj(path, mesh, mesh.vertices); }

} // namespace mocap
