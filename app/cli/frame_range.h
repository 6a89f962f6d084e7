#pragma once

#include "mocap/model/take.h"

#include <optional>
#include <string>
#include <utility>

namespace mocap::cli {

/// The take frame indices [begin, end) of `--frames FIRST:LAST` (frame numbers as the take numbers
/// them, both included); the whole take without the option. Throws UsageError for another form or
/// a range that is empty or leaves the take. O(1).
[[nodiscard]] std::pair<Eigen::Index, Eigen::Index> parseFrameRange(const std::optional<std::string>& text, const Take& take);

} // namespace mocap::cli
