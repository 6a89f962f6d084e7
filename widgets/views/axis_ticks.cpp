#include "views/axis_ticks.h"

#include <algorithm>
#include <cmath>

namespace mocap::ui {

double niceTickStep(double span, int count)
{
  const double raw = span / std::max(count, 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double factor : {1.0, 2.0, 5.0})
    if (raw <= factor * magnitude * (1.0 + 1e-9))
      return factor * magnitude;
  return 10.0 * magnitude;
}

AxisTicks niceTicks(double lo, double hi, int maxCount)
{
  AxisTicks ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi) || hi <= lo)
    return ticks;
  ticks.step = niceTickStep(hi - lo, std::max(maxCount, 1));
  ticks.decimals = std::max(0, static_cast<int>(-std::floor(std::log10(ticks.step) + 1e-9)));
  // Whole multiples k·step, so the values carry no accumulated rounding.
  const auto first = static_cast<long long>(std::ceil(lo / ticks.step - 1e-9));
  const auto last = static_cast<long long>(std::floor(hi / ticks.step + 1e-9));
  for (long long k = first; k <= last; ++k)
    ticks.values.push_back(static_cast<double>(k) * ticks.step);
  return ticks;
}

} // namespace mocap::ui
