#include "mocap/io/rig_io.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/io/gltf_rig_reader.h"
#include "mocap/io/obj_rig_reader.h"

namespace mocap {

bool isGltfPath(const std::filesystem::path& path)
{
  const std::string extension = lowerExtension(path);
  return extension == "glb" || extension == "gltf";
}

BlendshapeRig readRig(const std::filesystem::path& neutral, const std::filesystem::path& shapeFolder,
                      const std::vector<std::string>& only)
{
  if (isGltfPath(neutral)) {
    if (!shapeFolder.empty())
      throw InvalidArgument("a glTF rig holds its own shapes; no shape folder is read with " + neutral.string());
    return readGltfRig(neutral, only);
  }
  if (shapeFolder.empty())
    throw InvalidArgument("an OBJ/PLY neutral needs the folder with its shapes: " + neutral.string());
  return readObjRig(neutral, shapeFolder, only);
}

} // namespace mocap
