// libFuzzer entry for the PC2 point-cache reader: any input must load or raise mocap::Error.
#include "mocap/base/error.h"
#include "mocap/io/pc2_io.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  try {
    (void)mocap::parsePc2(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.pc2");
  } catch (const mocap::Error&) {
  }
  return 0;
}
