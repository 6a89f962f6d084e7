#pragma once

#include "mocap/model/take.h"

#include <optional>
#include <string>
#include <utility>

namespace mocap::cli {

/// The take frame indices [begin, end) of `--frames FIRST:LAST` (frame numbers as the take numbers
/// them, both included; parseIndexRange's form); the whole take without the option. Throws
/// UsageError naming the text and what is wrong for another form or a range that is reversed or
/// leaves the take. O(|text|).
[[nodiscard]] std::pair<Eigen::Index, Eigen::Index> parseFrameRange(const std::optional<std::string>& text, const Take& take);
/// The same for frames numbered firstFrame…firstFrame + frameCount - 1 (weight curves).
[[nodiscard]] std::pair<Eigen::Index, Eigen::Index> parseFrameRange(const std::optional<std::string>& text,
                                                                    long long firstFrame, Eigen::Index frameCount);

} // namespace mocap::cli
