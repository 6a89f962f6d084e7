#include "mocap/base/job_control.h"

#include <algorithm>

namespace mocap {

JobControl::JobControl(Progress progress, std::shared_ptr<const std::atomic<bool>> cancel)
    : m_progress(std::move(progress)), m_cancel(std::move(cancel)), m_throttle(std::make_shared<Throttle>())
{
}

void JobControl::checkpoint(double fraction) const
{
  if (cancelled())
    throw JobCancelled();
  if (!m_progress)
    return;
  const auto now = std::chrono::steady_clock::now();
  if (now - m_throttle->last < std::chrono::milliseconds(50))
    return;
  m_throttle->last = now;
  m_progress(m_begin + (m_end - m_begin) * std::clamp(fraction, 0.0, 1.0));
}

JobControl JobControl::part(double begin, double end) const
{
  JobControl part = *this;
  part.m_begin = m_begin + (m_end - m_begin) * begin;
  part.m_end = m_begin + (m_end - m_begin) * end;
  return part;
}

} // namespace mocap
