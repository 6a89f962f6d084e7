#pragma once

#include <atomic>
#include <chrono>
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

/// Progress and cancellation of a long computation, passed by the caller (the studio runs the
/// computation on a worker thread; the CLI passes the default, which does nothing). A job calls
/// checkpoint(fraction) between units of work: it reports progress at most every ~50 ms and
/// stops the job by throwing JobCancelled once cancel is set. Copies share the throttle.
class JobControl
{
public:
  using Progress = std::function<void(double fraction)>;

  JobControl() = default;
  /// `cancel` is shared so a job still running when its requester moved on keeps a valid flag.
  JobControl(Progress progress, std::shared_ptr<const std::atomic<bool>> cancel);

  /// Throws JobCancelled when cancelled; else reports `fraction` (clamped to 0…1) when ~50 ms
  /// passed since the last report. O(1).
  void checkpoint(double fraction) const;
  [[nodiscard]] bool cancelled() const { return m_cancel && m_cancel->load(std::memory_order_relaxed); }
  /// The control for a part of this job that covers [begin, end] of its progress: the part
  /// reports 0…1 of itself. Shares cancellation and throttle.
  [[nodiscard]] JobControl part(double begin, double end) const;

private:
  struct Throttle
  {
    std::chrono::steady_clock::time_point last{};
  };
  Progress m_progress;
  std::shared_ptr<const std::atomic<bool>> m_cancel;
  std::shared_ptr<Throttle> m_throttle;
  double m_begin = 0.0, m_end = 1.0;
};

} // namespace mocap
