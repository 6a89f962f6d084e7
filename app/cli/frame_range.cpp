#include "frame_range.h"

#include "cli_error.h"

#include <cstdio>

namespace mocap::cli {

std::pair<Eigen::Index, Eigen::Index> parseFrameRange(const std::optional<std::string>& text, const Take& take)
{
  if (!text)
    return {0, take.frameCount()};
  const std::size_t colon = text->find(':');
  long long first = 0, last = 0;
  if (colon == std::string::npos || std::sscanf(text->c_str(), "%lld:%lld", &first, &last) != 2)
    throw UsageError("--frames needs FIRST:LAST frame numbers, not '" + *text + "'");
  const long long begin = first - take.firstFrame(), end = last - take.firstFrame() + 1;
  if (begin < 0 || end > take.frameCount() || begin >= end)
    throw UsageError("--frames " + *text + " is outside the take or empty");
  return {static_cast<Eigen::Index>(begin), static_cast<Eigen::Index>(end)};
}

} // namespace mocap::cli
