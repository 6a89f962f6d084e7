#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace mocap {

/// The length unit of a take's marker positions and residuals.
enum class LengthUnit
{
  Millimetre,
  Centimetre,
  Metre,
};

/// "mm", "cm" or "m".
[[nodiscard]] std::string_view unitName(LengthUnit unit);

/// Parses "mm", "cm", "m" (also "millimeters", "meters"... case-insensitive, surrounding blanks ignored).
[[nodiscard]] std::optional<LengthUnit> parseLengthUnit(std::string_view text);

/// How many millimetres one `unit` is: 1, 10 or 1000.
[[nodiscard]] double millimetresPer(LengthUnit unit);

} // namespace mocap
