#include "ui_stall_meter.h"

#include <QEventLoop>

#include <algorithm>

namespace mocap::studio {

UiStallMeter::UiStallMeter(QObject* parent) : QObject(parent)
{
  m_timer.setTimerType(Qt::PreciseTimer);
  m_timer.setInterval(1);
  connect(&m_timer, &QTimer::timeout, this, &UiStallMeter::tick);
}

void UiStallMeter::start()
{
  m_clock.start();
  m_last = 0;
  m_longest = 0;
  m_stalls.clear();
  m_timer.start();
}

double UiStallMeter::stop()
{
  QEventLoop settle;
  QTimer::singleShot(30, &settle, &QEventLoop::quit);
  settle.exec();
  m_timer.stop();
  tick();
  return std::max(0.0, static_cast<double>(m_longest) * 1e-6 - 1.0);
}

void UiStallMeter::tick()
{
  const qint64 now = m_clock.nsecsElapsed();
  m_longest = std::max(m_longest, now - m_last);
  constexpr qint64 kRecordedNs = 10'000'000;
  if (now - m_last > kRecordedNs)
    m_stalls.push_back(now - m_last);
  m_last = now;
}

int UiStallMeter::stallsOver(double ms) const
{
  const auto limit = static_cast<qint64>((ms + 1.0) * 1e6);
  return static_cast<int>(std::count_if(m_stalls.begin(), m_stalls.end(), [limit](qint64 gap) { return gap > limit; }));
}

} // namespace mocap::studio
