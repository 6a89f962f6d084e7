#include "mocap/io/mesh_io.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/io/gltf_rig_reader.h"
#include "mocap/io/obj_io.h"
#include "mocap/io/ply_io.h"
#include "mocap/io/rig_io.h"

namespace mocap {

Mesh readMesh(const std::filesystem::path& path)
{
  const std::string extension = lowerExtension(path);
  if (extension == "obj")
    return readObj(path);
  if (extension == "ply")
    return readPly(path);
  if (isGltfPath(path))
    return readGltfRig(path).neutral;
  throw InvalidArgument(path.string() + ": unknown mesh format (use .obj, .ply, .glb or .gltf)");
}

} // namespace mocap
