#pragma once

#include <algorithm>

namespace mocap {

/// The smooth 0 → 1 step 3t² − 2t³ over [0, 1], clamped outside: zero slope at both ends, so a
/// blend that follows it leaves no kink where it starts or ends. O(1).
[[nodiscard]] inline double smoothStep(double t)
{
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

} // namespace mocap
