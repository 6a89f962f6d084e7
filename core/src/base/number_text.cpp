#include "mocap/base/number_text.h"

#include <charconv>

namespace mocap {

void appendNumber(std::string& out, double value)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

} // namespace mocap
