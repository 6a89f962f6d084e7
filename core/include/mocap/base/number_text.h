#pragma once

#include <string>
#include <string_view>

namespace mocap {

/// Appends the shortest decimal text that reads back to exactly `value` (std::to_chars), so
/// text formats round-trip doubles bit for bit. O(1).
void appendNumber(std::string& out, double value);

/// The whole of `text` as a number (std::from_chars; a leading '+' is taken, "nan" and "inf"
/// too, so check isfinite where they are not wanted). False when any of it is not. O(|text|).
[[nodiscard]] bool parseNumber(std::string_view text, double& value);

/// `value` with `decimals` decimals ("%.*f"), or `notFinite` for NaN and infinities, for text
/// tables and drawings. O(1).
[[nodiscard]] std::string fixedText(double value, int decimals, std::string_view notFinite);

/// A time as an SMPTE-style timecode HH:MM:SS:FF.mmm counting frames at `frameRate` rounded to
/// whole frames per second (Live Link Face's timecode; the thousandths are the fraction of a
/// frame). O(1).
[[nodiscard]] std::string timecodeText(double seconds, double frameRate);

} // namespace mocap
