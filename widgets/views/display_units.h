#pragma once

#include "mocap/base/length_unit.h"

#include <QString>

namespace mocap::ui {

/// `value` (in the take's unit `from`) as text in the display unit `to`, with the decimals that
/// keep a tenth of a millimetre visible, without the unit name. O(1).
[[nodiscard]] QString formatLength(double value, LengthUnit from, LengthUnit to);

/// "mm", "cm" or "m". O(1).
[[nodiscard]] QString unitLabel(LengthUnit unit);

} // namespace mocap::ui
