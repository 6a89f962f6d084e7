#pragma once

#include <vector>

namespace mocap::ui {

/// A "nice" tick spacing (1, 2 or 5 × 10ⁿ) giving about `count` ticks over `span` (> 0). O(1).
[[nodiscard]] double niceTickStep(double span, int count);

/// Tick positions for an axis from `lo` to `hi`: every multiple of a nice step inside [lo, hi],
/// at most about `maxCount` of them, with the decimals that tell them apart.
struct AxisTicks
{
  double step = 1.0;
  std::vector<double> values;  ///< ascending, each a whole multiple of step
  int decimals = 0;            ///< enough to show `step` exactly (0 for steps ≥ 1)
};

/// The ticks of [lo, hi] (in the unit the labels show). Empty values when the range is empty or
/// not finite. O(maxCount).
[[nodiscard]] AxisTicks niceTicks(double lo, double hi, int maxCount);

} // namespace mocap::ui
