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
  m_last = now;
}

} // namespace mocap::studio
