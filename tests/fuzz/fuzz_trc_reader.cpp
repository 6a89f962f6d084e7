// libFuzzer entry for the TRC reader: any input must load or raise mocap::Error.
#include "mocap/base/error.h"
#include "mocap/io/trc_io.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  try {
    (void)mocap::parseTrc(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.trc");
  } catch (const mocap::Error&) {
  }
  return 0;
}
