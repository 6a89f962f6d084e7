// libFuzzer entry for the glTF rig reader (GLB or JSON, told apart by the magic): any input must
// load or raise mocap::Error, and a rig that loads must pass checkRig, which the solver relies on.
// No base folder is given, so no input makes the reader open other files.
#include "mocap/base/error.h"
#include "mocap/io/gltf_rig_reader.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  mocap::BlendshapeRig rig;
  try {
    rig = mocap::parseGltfRig(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.glb");
  } catch (const mocap::Error&) {
    return 0;
  }
  mocap::checkRig(rig);  // outside the try: throwing here is a finding
  return 0;
}
