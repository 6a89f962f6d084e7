// libFuzzer entry for the PLY reader (ascii and binary little endian): any input must load or
// raise mocap::Error.
#include "mocap/base/error.h"
#include "mocap/io/ply_io.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  try {
    (void)mocap::parsePly(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.ply");
  } catch (const mocap::Error&) {
  }
  return 0;
}
