// libFuzzer entry for the mesh binding reader: any input must load or raise mocap::Error, and a
// binding that loads points only at vertices of the mesh (the deformers index with them).
#include "mocap/base/error.h"
#include "mocap/deform/mesh_binding.h"

#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  constexpr Eigen::Index kVertices = 468;  // the canonical face mesh of the seeds
  mocap::MeshBinding binding;
  try {
    binding = mocap::parseBinding(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.binding.json",
                                  kVertices);
  } catch (const mocap::Error&) {
    return 0;
  }
  for (const mocap::MarkerBinding& marker : binding.markers)
    for (const Eigen::Index v : marker.point.vertices)
      if (v < 0 || v >= kVertices)
        std::abort();
  return 0;
}
