#pragma once

#include <string>

namespace mocap {

/// Appends the shortest decimal text that reads back to exactly `value` (std::to_chars), so
/// text formats round-trip doubles bit for bit. O(1).
void appendNumber(std::string& out, double value);

} // namespace mocap
