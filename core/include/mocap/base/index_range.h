#pragma once

#include <cstdint>
#include <string_view>

namespace mocap {

/// The whole numbers FIRST…LAST, both included.
struct IndexRange
{
  std::int64_t first = 0;
  std::int64_t last = 0;
};

/// Reads "FIRST:LAST" (frame numbers, vertex indices): two decimal whole numbers, each with an
/// optional sign and blanks around it, with lowest ≤ FIRST ≤ LAST ≤ highest; nothing else may
/// follow. Throws InvalidArgument naming the bad part: no ':', an empty part, one that is not a
/// whole number (trailing text included) or does not fit 64 bits, LAST before FIRST, a number
/// below `lowest` or above `highest`. O(|text|).
[[nodiscard]] IndexRange parseIndexRange(std::string_view text, std::int64_t lowest, std::int64_t highest);

} // namespace mocap
