#include "views/display_units.h"

namespace mocap::ui {

QString formatLength(double value, LengthUnit from, LengthUnit to)
{
  const double converted = value * millimetresPer(from) / millimetresPer(to);
  const int decimals = to == LengthUnit::Millimetre ? 1 : to == LengthUnit::Centimetre ? 2 : 4;
  return QString::number(converted, 'f', decimals);
}

QString unitLabel(LengthUnit unit)
{
  const std::string_view name = unitName(unit);
  return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
}

} // namespace mocap::ui
