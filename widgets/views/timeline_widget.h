#pragma once

#include <QElapsedTimer>
#include <QWidget>

#include <Eigen/Core>

#include <utility>
#include <vector>

class QComboBox;
class QLabel;
class QSpinBox;
class QTimer;
class QToolButton;

namespace mocap::ui {

class TakeDocument;
class TimelineSlider;

/// Play/pause, step, jump to the previous/next gap of the selection, loop and speed, with the
/// frame number and time. Playback follows the wall clock at the take's rate × speed, so it
/// keeps real time even when a frame takes long to draw (frames are skipped, not slowed).
/// The slider marks the gaps (upper half) and the bad points under review (lower half, flag
/// colour) of the selected markers, or of all markers when none is selected, and the selected
/// frame range; the marks are worked out per pixel column once per change of the take,
/// selection, flags or width, so painting costs O(width) whatever the take's size.
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
  /// With no marker selected, it goes through the gaps of every marker in (frame, marker) order
  /// and selects the marker of each gap it reaches, and keeps doing so while that selection
  /// stands. Says where it went through message().
  void jumpToGap(int direction);
  /// Moves to the next (1) or previous (−1) flagged sample (bad point under review) of the
  /// selected markers, or of all markers when none is selected.
  /// Says in the status bar which markers are flagged there and how far each is off its neighbours.
  void jumpToFlag(int direction);
  [[nodiscard]] double speed() const { return m_speed; }

  /// Where the slider draws frame `frame` (x in slider coordinates).
  [[nodiscard]] int tickX(Eigen::Index frame) const;
  /// The runs of pixel columns [x0, x1] (slider coordinates) marked as gaps / bad points.
  [[nodiscard]] std::vector<std::pair<int, int>> gapTickSpans() const;
  [[nodiscard]] std::vector<std::pair<int, int>> flagTickSpans() const;

signals:
  /// Something to tell the user (e.g. which gap a jump went to), for the status bar.
  void message(const QString& text);

private:
  void syncFromDocument();
  void jumpTo(Eigen::Index frame);
  /// "M12, 14.2 mm off the mid-point of its neighbours" (the label alone at a take's end or a gap).
  [[nodiscard]] QString flagDescription(Eigen::Index marker, Eigen::Index frame) const;
  void advance();

  TakeDocument& m_document;
  QToolButton* m_play = nullptr;
  QToolButton* m_loop = nullptr;
  TimelineSlider* m_slider = nullptr;
  QSpinBox* m_frame = nullptr;
  QLabel* m_time = nullptr;
  QComboBox* m_speedBox = nullptr;
  QTimer* m_timer = nullptr;
  QElapsedTimer m_clock;
  Eigen::Index m_startFrame = 0;
  double m_speed = 1.0;
  // The gap the last jump went to, so the next one continues from it, and the selection it made.
  Eigen::Index m_jumpFrame = -1;
  Eigen::Index m_jumpMarker = -1;
  std::vector<Eigen::Index> m_jumpSelection;
};

} // namespace mocap::ui
