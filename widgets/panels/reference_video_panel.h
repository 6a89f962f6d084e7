#pragma once

#include <QString>
#include <QWidget>

#include <cstddef>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QStackedWidget;

namespace mocap::ui {

class ReferenceVideo;
class ReferenceVideos;
class StudioSession;
class TakeDocument;
class VideoView;

/// The Reference Video dock: the take's reference videos (any file Debian's FFmpeg decodes:
/// MP4/H.264, MOV, AVI, MKV), one shown at a time, picked in a list; Add Reference Video… and
/// Remove. For the shown video: its rate, length and codec (and whether its frame rate varies),
/// its offset against the take (seconds, typed or nudged by one video frame with the buttons or
/// Alt+, / Alt+.), and its frame for the current take frame (VideoView), decoded on a worker so
/// scrubbing never waits. Lining up: type or step the video to a moment (the video is then held
/// there), step the take to the same moment and press Sync here; or Sync to event puts the video's
/// first frame (or the held one) at a sync event of the take.
///
/// The videos, their offsets and the sidecar beside the take belong to the session
/// (StudioSession::referenceVideos); the dock shows and edits them.
class ReferenceVideoPanel final : public QWidget
{
  Q_OBJECT

public:
  explicit ReferenceVideoPanel(StudioSession& session, QWidget* parent = nullptr);
  ~ReferenceVideoPanel() override;

  /// Adds `path` as a reference video of the take (or shows it, when already linked) and shows it;
  /// returns "" or the error shown.
  QString openVideo(const QString& path);
  /// Removes video `index` from the take (and from its sidecar).
  void removeVideo(int index);
  /// Opens `path` as missing video `index`, keeping its offset; returns "" or the error shown.
  QString locateVideo(int index, const QString& path);
  /// Shows video `index`.
  void setCurrentIndex(int index);
  /// The shown video, or an empty one when the take has none.
  [[nodiscard]] ReferenceVideo& video() const;
  [[nodiscard]] VideoView& view() const;

  /// Sync here: the offset that shows the held video frame at the current take frame.
  void syncHere();
  /// The events of the take offered for syncing (their indices into Take::events()), the likely
  /// sync event first; empty when the take has none.
  [[nodiscard]] const std::vector<std::size_t>& syncEvents() const { return m_events; }
  /// Sync to event: the take's event `eventIndex` shows the held video frame, or the first.
  QString syncToEvent(std::size_t eventIndex);

  [[nodiscard]] QString statusText() const;
  /// What the Video frame box reads: the frame shown, or "none" where the take has no video frame.
  [[nodiscard]] QString videoFrameText() const;

private:
  void openDialog();
  void locateDialog();
  void videoInserted(int index);
  void videoAboutToBeRemoved(int index);
  void currentChanged(int index);
  void restored(int count, int missing, const QString& problem);
  void updateInfo();
  void updateEvents();
  void nudgeOrStep(int frames);

  TakeDocument& m_document;
  ReferenceVideos& m_videos;
  std::vector<VideoView*> m_views;  // one per video of m_videos
  ReferenceVideo* m_none = nullptr;  // shown when the take has no video
  VideoView* m_noneView = nullptr;
  QStackedWidget* m_stack = nullptr;
  QComboBox* m_choice = nullptr;
  QLabel* m_info = nullptr;
  QDoubleSpinBox* m_offset = nullptr;
  QSpinBox* m_frame = nullptr;
  QPushButton* m_remove = nullptr;
  QPushButton* m_locate = nullptr;
  QPushButton* m_syncHere = nullptr;
  QPushButton* m_follow = nullptr;
  QComboBox* m_eventChoice = nullptr;
  QPushButton* m_syncEvent = nullptr;
  QLabel* m_status = nullptr;

  std::vector<std::size_t> m_events;
};

} // namespace mocap::ui
