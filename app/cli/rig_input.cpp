#include "rig_input.h"

#include "arguments.h"
#include "cli_error.h"

#include "mocap/io/rig_io.h"

namespace mocap::cli {

BlendshapeRig readInputRig(const std::string& mesh, const std::string& shapes, const std::optional<std::string>& only)
{
  if (!isGltfPath(mesh) && shapes.empty())
    throw UsageError("--shapes DIR is needed with an OBJ/PLY neutral");
  if (isGltfPath(mesh) && !shapes.empty())
    throw UsageError("--shapes is not used with a glTF rig: it holds its own shapes");
  return readRig(mesh, shapes, only ? splitList(*only, "--only") : std::vector<std::string>{});
}

} // namespace mocap::cli
