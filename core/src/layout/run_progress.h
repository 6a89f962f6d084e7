#pragma once
// Threads and progress of a long layout run (RunControl, marker_selection.h), shared by the
// selection methods and the layout plan; private to core/src/layout.

#include "mocap/base/parallel_for.h"
#include "mocap/layout/marker_selection.h"

#include <algorithm>
#include <chrono>

namespace mocap::layout_internal {

using Clock = std::chrono::steady_clock;

// The threads a run uses: RunControl::threads, or all the hardware has. O(1).
inline int threadCount(const RunControl& control)
{
  if (control.threads > 0)
    return control.threads;
  return hardwareThreads();
}

// Rate-limited progress on the calling thread.
class ProgressReporter
{
public:
  explicit ProgressReporter(const RunControl& control) : m_control(control) {}
  void report(double fraction, bool force = false)
  {
    if (!m_control.progress)
      return;
    const auto now = Clock::now();
    if (!force && now - m_last < std::chrono::milliseconds(50))
      return;
    m_last = now;
    m_control.progress(std::clamp(fraction, 0.0, 1.0));
  }

private:
  const RunControl& m_control;
  Clock::time_point m_last = Clock::now() - std::chrono::seconds(1);
};

} // namespace mocap::layout_internal
