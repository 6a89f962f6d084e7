#pragma once

#include <QElapsedTimer>
#include <QWidget>

#include <Eigen/Core>

class QComboBox;
class QLabel;
class QSlider;
class QSpinBox;
class QTimer;
class QToolButton;

namespace mocap::ui {

class TakeDocument;

/// Play/pause, step, jump to the previous/next gap of the selection, loop and speed, with the
/// frame number and time. Playback follows the wall clock at the take's rate × speed, so it
/// keeps real time even when a frame takes long to draw (frames are skipped, not slowed).
class TimelineWidget final : public QWidget
{
  Q_OBJECT

public:
  explicit TimelineWidget(TakeDocument& document, QWidget* parent = nullptr);

  [[nodiscard]] bool isPlaying() const;
  void setPlaying(bool playing);
  void togglePlaying() { setPlaying(!isPlaying()); }
  void step(int frames);
  /// Moves to the start of the next (direction 1) or previous (−1) gap of the selected markers.
  void jumpToGap(int direction);
  /// Moves to the next (1) or previous (−1) flagged sample (bad point under review) of the
  /// selected markers, or of all markers when none is selected.
  void jumpToFlag(int direction);
  [[nodiscard]] double speed() const { return m_speed; }

private:
  void syncFromDocument();
  void jumpTo(Eigen::Index frame);
  void advance();

  TakeDocument& m_document;
  QToolButton* m_play = nullptr;
  QToolButton* m_loop = nullptr;
  QSlider* m_slider = nullptr;
  QSpinBox* m_frame = nullptr;
  QLabel* m_time = nullptr;
  QComboBox* m_speedBox = nullptr;
  QTimer* m_timer = nullptr;
  QElapsedTimer m_clock;
  Eigen::Index m_startFrame = 0;
  double m_speed = 1.0;
};

} // namespace mocap::ui
