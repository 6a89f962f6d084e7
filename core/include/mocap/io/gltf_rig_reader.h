#pragma once

#include "mocap/model/blendshape_rig.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// Reads a blendshape rig from a glTF 2.0 file, binary (.glb) or JSON (.gltf, buffers external or
/// embedded as data URIs), as Blender, Maya, three.js and rigGlb write it. The rig is the first
/// mesh with morph targets: all its triangle primitives merged into one neutral (each
/// primitive's vertices after the previous ones'; a primitive without indices draws its vertices
/// in order; zero-area triangles with a repeated index are dropped), and one shape per morph
/// target from the targets' POSITION deltas, keeping the vertices that move at all. Shape names
/// come from the mesh's `extras.targetNames`; without it, or with another count, they are
/// "shape_0", "shape_1", …. Node transforms are ignored: the rig is in the mesh's own space and
/// units. Positions must be float (quantized meshes, KHR_mesh_quantization, and compressed ones,
/// Draco or meshopt, are refused). `only`: just these shapes, in this order (all when empty).
///
/// Nothing half-loaded. Throws IoError when the file cannot be read; FormatError for anything
/// wrong in it — not glTF, a truncated GLB, no mesh with morph targets, a mode other than
/// triangles, primitives with different target counts, an accessor or view out of its buffer's
/// range, an index out of range, duplicate or empty names, a non-finite coordinate, primitives or
/// morph targets that reuse accessors until the accessor data read passes 16 times the bytes the
/// buffers hold (plus 64 KiB; a real rig reads each byte about once), refused before it is read; and
/// InvalidArgument for a name in `only` the rig lacks or gives twice.
/// O(file size + #targets · #vertices).
[[nodiscard]] BlendshapeRig readGltfRig(const std::filesystem::path& path, const std::vector<std::string>& only = {});

/// Parses glTF bytes (GLB or JSON, told apart by the GLB magic) as readGltfRig does; `sourceName`
/// names them in errors. External buffers are read from `baseDir`; with an empty `baseDir` a
/// file that refers to one is a FormatError (data URIs and the GLB's own chunk still work).
[[nodiscard]] BlendshapeRig parseGltfRig(std::string_view bytes, const std::string& sourceName,
                                         const std::filesystem::path& baseDir = {},
                                         const std::vector<std::string>& only = {});

} // namespace mocap
