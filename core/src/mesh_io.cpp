#include "mocap/mesh_io.h"

#include "mocap/error.h"
#include "mocap/file_io.h"
#include "mocap/obj_io.h"
#include "mocap/ply_io.h"

namespace mocap {

Mesh readMesh(const std::filesystem::path& path)
{
  const std::string extension = lowerExtension(path);
  if (extension == "obj")
    return readObj(path);
  if (extension == "ply")
    return readPly(path);
  throw InvalidArgument(path.string() + ": unknown mesh format (use .obj or .ply)");
}

} // namespace mocap
