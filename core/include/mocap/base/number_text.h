#pragma once

#include <string>

namespace mocap {

/// Appends the shortest decimal text that reads back to exactly `value` (std::to_chars), so
/// text formats round-trip doubles bit for bit. O(1).
void appendNumber(std::string& out, double value);

/// A time as an SMPTE-style timecode HH:MM:SS:FF.mmm counting frames at `frameRate` rounded to
/// whole frames per second (Live Link Face's timecode; the thousandths are the fraction of a
/// frame). O(1).
[[nodiscard]] std::string timecodeText(double seconds, double frameRate);

} // namespace mocap
