#pragma once

#include "mocap/base/job_control.h"

#include <pybind11/pybind11.h>

#include <atomic>
#include <memory>

namespace mocap::python {

/// Progress and cancellation of a core call made with the GIL released. Each report (throttled
/// by JobControl to one per ~50 ms, from any thread) takes the GIL, checks for Ctrl+C and calls
/// the Python `progress(fraction)` when one was given; Ctrl+C, a callback that returns False or
/// raises cancels the job, which then stops at its next checkpoint.
class PythonJob
{
public:
  explicit PythonJob(pybind11::object progress);

  /// The control to hand to the core call.
  [[nodiscard]] JobControl control() const;
  /// After the call threw JobCancelled, with the GIL held: raises what stopped it (the
  /// KeyboardInterrupt or the callback's exception), or mocap.Cancelled for a callback's False.
  [[noreturn]] void raiseCancelled();

private:
  void report(double fraction);

  pybind11::object m_progress;
  std::shared_ptr<std::atomic<bool>> m_cancel = std::make_shared<std::atomic<bool>>(false);
  std::shared_ptr<pybind11::error_already_set> m_error;  // what stopped the job, if Python raised
};

/// Runs `work(control)` with the GIL released under a PythonJob for `progress` and returns its
/// result; a cancelled run raises as PythonJob::raiseCancelled says.
template <typename Work>
auto runReleased(const pybind11::object& progress, Work&& work)
{
  PythonJob job(progress);
  try {
    const pybind11::gil_scoped_release release;
    return work(job.control());
  } catch (const JobCancelled&) {
    job.raiseCancelled();
  }
}

} // namespace mocap::python
