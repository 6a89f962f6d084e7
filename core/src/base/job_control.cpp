#include "mocap/base/job_control.h"

#include <algorithm>
#include <chrono>
#include <limits>

namespace mocap {

namespace {
using Clock = std::chrono::steady_clock;
constexpr auto kReportInterval = std::chrono::milliseconds(50);

long long ticksNow()
{
  return static_cast<long long>(Clock::now().time_since_epoch().count());
}
} // namespace

JobControl::JobControl(Progress progress, std::shared_ptr<const std::atomic<bool>> cancel)
    : m_progress(std::move(progress)), m_cancel(std::move(cancel)),
      m_lastReport(std::make_shared<std::atomic<long long>>(std::numeric_limits<long long>::min()))
{
}

void JobControl::checkpoint(double fraction) const
{
  if (cancelled())
    throw JobCancelled();
  report(fraction);
}

void JobControl::report(double fraction) const
{
  if (!m_progress)
    return;
  const long long now = ticksNow();
  const auto interval = std::chrono::duration_cast<Clock::duration>(kReportInterval).count();
  long long last = m_lastReport->load(std::memory_order_relaxed);
  // One thread wins each interval; the others skip their report.
  if ((last != std::numeric_limits<long long>::min() && now - last < interval) ||
      !m_lastReport->compare_exchange_strong(last, now, std::memory_order_relaxed))
    return;
  send(fraction);
}

void JobControl::reportNow(double fraction) const
{
  if (!m_progress)
    return;
  m_lastReport->store(ticksNow(), std::memory_order_relaxed);
  send(fraction);
}

void JobControl::send(double fraction) const
{
  m_progress(m_begin + (m_end - m_begin) * std::clamp(fraction, 0.0, 1.0));
}

JobControl JobControl::part(double begin, double end) const
{
  JobControl part = *this;
  part.m_begin = m_begin + (m_end - m_begin) * begin;
  part.m_end = m_begin + (m_end - m_begin) * end;
  return part;
}

JobControl JobControl::silent() const
{
  JobControl control = *this;
  control.m_progress = nullptr;
  return control;
}

JobControl JobControl::withThreads(int threads) const
{
  JobControl control = *this;
  control.m_threads = std::max(threads, 0);
  return control;
}

} // namespace mocap
