// libFuzzer entry for the C3D reader: any input must load or raise mocap::Error.
#include "mocap/io/c3d_reader.h"
#include "mocap/base/error.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  try {
    (void)mocap::parseC3d(data, size, "fuzz.c3d");
  } catch (const mocap::Error&) {
  }
  return 0;
}
