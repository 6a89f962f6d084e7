#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <stdexcept>

namespace mocap {

/// Thrown by JobControl::checkpoint when the job was cancelled: the computation unwinds and its
/// partial result is dropped (nothing it would have changed was changed).
class JobCancelled : public std::runtime_error
{
public:
  JobCancelled() : std::runtime_error("cancelled") {}
};

/// Threads, progress and cancellation of a long computation, passed by the caller (the studio runs
/// the computation on a worker through its JobRunner; the CLI passes a progress line or the
/// default, which does nothing). A job stops in one of two ways:
/// - checkpoint(fraction) between units of work throws JobCancelled once cancel is set (the
///   computation unwinds and drops what it did);
/// - a computation that returns what is complete (a PFA sweep's finished k) polls cancelled() or
///   hands cancelFlag() to parallelFor, and reports with report().
/// Reports are throttled to one per ~50 ms (copies and parts share the throttle, from any
/// thread); reportNow() forces one (the first and the last).
class JobControl
{
public:
  using Progress = std::function<void(double fraction)>;

  JobControl() = default;
  /// `cancel` is shared so a job still running when its requester moved on keeps a valid flag.
  JobControl(Progress progress, std::shared_ptr<const std::atomic<bool>> cancel = {});

  /// Throws JobCancelled when cancelled; else report(fraction). O(1).
  void checkpoint(double fraction) const;
  /// Reports `fraction` (clamped to 0…1) when ~50 ms passed since the last report. O(1).
  void report(double fraction) const;
  /// Reports `fraction` now, whenever the last report was. O(1).
  void reportNow(double fraction) const;
  [[nodiscard]] bool cancelled() const { return m_cancel && m_cancel->load(std::memory_order_relaxed); }
  /// The flag cancel sets, for parallelFor (null when the job cannot be cancelled).
  [[nodiscard]] const std::atomic<bool>* cancelFlag() const { return m_cancel.get(); }
  /// The control for a part of this job that covers [begin, end] of its progress: the part
  /// reports 0…1 of itself. Shares threads, cancellation and throttle.
  [[nodiscard]] JobControl part(double begin, double end) const;
  /// This control without progress reports, for the steps of parallel work whose own fractions
  /// mean nothing to the whole (it still stops them).
  [[nodiscard]] JobControl silent() const;
  /// The threads a parallel job may use; 0: every hardware thread (parallelFor's ≤ 0).
  [[nodiscard]] int threads() const { return m_threads; }
  /// This control on `threads` threads (≤ 0: every hardware thread). Results of a parallel job
  /// do not depend on the thread count.
  [[nodiscard]] JobControl withThreads(int threads) const;

private:
  void send(double fraction) const;

  Progress m_progress;
  std::shared_ptr<const std::atomic<bool>> m_cancel;
  std::shared_ptr<std::atomic<long long>> m_lastReport;  // steady-clock ticks of the last report
  double m_begin = 0.0, m_end = 1.0;
  int m_threads = 0;
};

} // namespace mocap
