// libFuzzer entry for the marker-set file reader: any input must load or raise mocap::Error, and
// a set that loads must pass validateMarkerSet (every consumer relies on it).
#include "mocap/base/error.h"
#include "mocap/io/marker_set_io.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  mocap::MarkerSet set;
  try {
    set = mocap::parseMarkerSet(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const mocap::Error&) {
    return 0;
  }
  mocap::validateMarkerSet(set);  // outside the try: throwing here is a finding
  return 0;
}
