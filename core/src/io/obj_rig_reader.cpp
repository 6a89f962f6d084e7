#include "mocap/io/obj_rig_reader.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/parallel_for.h"
#include "mocap/io/mesh_io.h"
#include "mocap/io/obj_io.h"

#include <algorithm>

namespace mocap {

namespace {

std::vector<std::filesystem::path> shapeFiles(const std::filesystem::path& neutral, const std::filesystem::path& folder)
{
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    throw IoError("shape folder '" + folder.string() + "' is not a directory");
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error))
    if (entry.is_regular_file() && lowerExtension(entry.path()) == "obj" &&
        !std::filesystem::equivalent(entry.path(), neutral, error))
      files.push_back(entry.path());
  if (error)
    throw IoError("cannot list shape folder '" + folder.string() + "': " + error.message());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::filesystem::path> selectFiles(const std::vector<std::filesystem::path>& files,
                                               const std::vector<std::string>& only, const std::filesystem::path& folder)
{
  if (only.empty())
    return files;
  std::vector<std::filesystem::path> selected;
  for (const std::string& name : only) {
    const auto it = std::find_if(files.begin(), files.end(), [&](const auto& f) { return f.stem().string() == name; });
    if (it == files.end())
      throw InvalidArgument("shape folder '" + folder.string() + "' has no " + name + ".obj");
    selected.push_back(*it);
  }
  return selected;
}

} // namespace

BlendshapeRig readObjRig(const std::filesystem::path& neutral, const std::filesystem::path& shapeFolder,
                         const std::vector<std::string>& only)
{
  BlendshapeRig rig;
  rig.neutral = readMesh(neutral);
  const std::vector<std::filesystem::path> files = selectFiles(shapeFiles(neutral, shapeFolder), only, shapeFolder);
  if (files.empty())
    throw IoError("shape folder '" + shapeFolder.string() + "' has no .obj shapes");
  // Unmoved vertices are written with the neutral's digits; the tolerance only absorbs rounding.
  const double tolerance = 1e-9 * std::max(rig.neutral.size(), 1e-300);
  rig.shapes.resize(files.size());
  (void)parallelFor(files.size(), 0, [&](std::size_t i) {
    const Mesh shape = readObj(files[i]);
    try {
      rig.shapes[i] = sparseShape(files[i].stem().string(), rig.neutral.vertices, shape.vertices, tolerance);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(files[i].string() + ": " + e.what());
    }
  });
  checkRig(rig);
  return rig;
}

} // namespace mocap
