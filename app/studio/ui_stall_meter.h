#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <vector>

namespace mocap::studio {

/// Measures how long the UI thread went without serving its event loop: a 1 ms timer notes the
/// longest gap between its ticks while running. What a user feels as a frozen window.
class UiStallMeter final : public QObject
{
public:
  explicit UiStallMeter(QObject* parent = nullptr);

  void start();
  /// Serves the event loop ~30 ms more (so a stall just before is closed by a tick), stops and
  /// returns the longest gap between ticks in ms, less the timer's own 1 ms.
  double stop();
  /// How many gaps between ticks of the last run were longer than `ms` (less the timer's 1 ms).
  [[nodiscard]] int stallsOver(double ms) const;

private:
  void tick();

  QTimer m_timer;
  QElapsedTimer m_clock;
  qint64 m_last = 0;
  qint64 m_longest = 0;
  std::vector<qint64> m_stalls;  // the gaps over 10 ms (ns)
};

} // namespace mocap::studio
