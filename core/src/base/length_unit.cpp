#include "mocap/base/length_unit.h"

#include "mocap/base/enum_table.h"
#include "mocap/base/text.h"

namespace mocap {

namespace {

// The symbol first (the name), then the spelled-out aliases a file's UNITS may hold.
constexpr EnumTable<LengthUnit, 15> kUnits{{{
    {LengthUnit::Millimetre, "mm"},
    {LengthUnit::Centimetre, "cm"},
    {LengthUnit::Metre, "m"},
    {LengthUnit::Millimetre, "millimeter"},
    {LengthUnit::Millimetre, "millimeters"},
    {LengthUnit::Millimetre, "millimetre"},
    {LengthUnit::Millimetre, "millimetres"},
    {LengthUnit::Centimetre, "centimeter"},
    {LengthUnit::Centimetre, "centimeters"},
    {LengthUnit::Centimetre, "centimetre"},
    {LengthUnit::Centimetre, "centimetres"},
    {LengthUnit::Metre, "meter"},
    {LengthUnit::Metre, "meters"},
    {LengthUnit::Metre, "metre"},
    {LengthUnit::Metre, "metres"},
}}};

} // namespace

std::string_view unitName(LengthUnit unit)
{
  return kUnits.name(unit, "mm");
}

std::optional<LengthUnit> parseLengthUnit(std::string_view text)
{
  return kUnits.parse(toLower(trim(text)));
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
