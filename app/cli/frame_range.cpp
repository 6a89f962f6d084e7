#include "frame_range.h"

#include "cli_error.h"

#include "mocap/base/error.h"
#include "mocap/base/index_range.h"

namespace mocap::cli {

std::pair<Eigen::Index, Eigen::Index> parseFrameRange(const std::optional<std::string>& text, const Take& take)
{
  return parseFrameRange(text, take.firstFrame(), take.frameCount());
}

std::pair<Eigen::Index, Eigen::Index> parseFrameRange(const std::optional<std::string>& text, long long firstFrame,
                                                      Eigen::Index frameCount)
{
  if (!text)
    return {0, frameCount};
  const std::int64_t first = firstFrame, last = first + frameCount - 1;
  try {
    const IndexRange range = parseIndexRange(*text, first, last);
    return {static_cast<Eigen::Index>(range.first - first), static_cast<Eigen::Index>(range.last - first + 1)};
  } catch (const InvalidArgument& e) {
    throw UsageError("--frames needs FIRST:LAST frame numbers of the take (" + std::to_string(first) + "…" +
                     std::to_string(last) + "), not '" + *text + "': " + e.what());
  }
}

} // namespace mocap::cli
