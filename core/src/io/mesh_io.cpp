#include "mocap/io/mesh_io.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/io/obj_io.h"
#include "mocap/io/ply_io.h"

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
