// libFuzzer entry for the OBJ reader: any input must load or raise mocap::Error, and a mesh that
// loads must pass checkMesh (indices in range, finite coordinates), which the viewers rely on.
#include "mocap/base/error.h"
#include "mocap/io/obj_io.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  mocap::Mesh mesh;
  try {
    mesh = mocap::parseObj(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.obj");
  } catch (const mocap::Error&) {
    return 0;
  }
  mocap::checkMesh(mesh);  // outside the try: throwing here is a finding
  return 0;
}
