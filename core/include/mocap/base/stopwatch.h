#pragma once

#include <chrono>

namespace mocap {

/// Wall-clock seconds since construction (steady clock), for the timings commands report. O(1).
class Stopwatch
{
public:
  [[nodiscard]] double seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
  }

private:
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

} // namespace mocap
