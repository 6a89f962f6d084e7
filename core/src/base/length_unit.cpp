#include "mocap/base/length_unit.h"

#include "mocap/base/text.h"

namespace mocap {

std::string_view unitName(LengthUnit unit)
{
  switch (unit) {
  case LengthUnit::Millimetre: return "mm";
  case LengthUnit::Centimetre: return "cm";
  case LengthUnit::Metre: return "m";
  }
  return "mm";
}

std::optional<LengthUnit> parseLengthUnit(std::string_view text)
{
  const std::string key = toLower(trim(text));
  if (key == "mm" || key == "millimeter" || key == "millimeters" || key == "millimetre" ||
      key == "millimetres")
    return LengthUnit::Millimetre;
  if (key == "cm" || key == "centimeter" || key == "centimeters" || key == "centimetre" ||
      key == "centimetres")
    return LengthUnit::Centimetre;
  if (key == "m" || key == "meter" || key == "meters" || key == "metre" || key == "metres")
    return LengthUnit::Metre;
  return std::nullopt;
}

double millimetresPer(LengthUnit unit)
{
  switch (unit) {
  case LengthUnit::Millimetre: return 1.0;
  case LengthUnit::Centimetre: return 10.0;
  case LengthUnit::Metre: return 1000.0;
  }
  return 1.0;
}

} // namespace mocap
