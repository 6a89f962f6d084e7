#pragma once

#include "mocap/video/reference_video_sidecar.h"

#include <QString>
#include <QTimer>
#include <QWidget>

#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QStackedWidget;

namespace mocap::ui {

class ReferenceVideo;
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
/// The videos and offsets are remembered beside the take in TAKE.video.json (see
/// reference_video_sidecar.h), written a moment after each change, and restored when the take is
/// opened; a video missing then stays linked (Locate… finds it) and nothing in the sidecar is lost.
class ReferenceVideoPanel final : public QWidget
{
  Q_OBJECT

public:
  explicit ReferenceVideoPanel(TakeDocument& document, QWidget* parent = nullptr);
  ~ReferenceVideoPanel() override;

  /// Adds `path` as a reference video of the take (or shows it, when already linked) and shows it;
  /// returns "" or the error shown.
  QString openVideo(const QString& path);
  /// Removes video `index` from the take (and from its sidecar).
  void removeVideo(int index);
  /// Opens `path` as missing video `index`, keeping its offset; returns "" or the error shown.
  QString locateVideo(int index, const QString& path);

  [[nodiscard]] int videoCount() const { return static_cast<int>(m_entries.size()); }
  [[nodiscard]] int currentIndex() const { return m_current; }
  void setCurrentIndex(int index);
  /// The shown video, or an empty one when the take has none.
  [[nodiscard]] ReferenceVideo& video() const;
  [[nodiscard]] ReferenceVideo& video(int index) const;
  [[nodiscard]] VideoView& view() const;
  /// Whether video `index` was not found when the take was opened (or cannot be opened).
  [[nodiscard]] bool isMissing(int index) const;

  /// Sync here: the offset that shows the held video frame at the current take frame.
  void syncHere();
  /// The events of the take offered for syncing (their indices into Take::events()), the likely
  /// sync event first; empty when the take has none.
  [[nodiscard]] const std::vector<std::size_t>& syncEvents() const { return m_events; }
  /// Sync to event: the take's event `eventIndex` shows the held video frame, or the first.
  QString syncToEvent(std::size_t eventIndex);

  /// Writes a pending change to the sidecar now (it is written a moment after each change).
  void saveSidecar();
  [[nodiscard]] QString statusText() const;
  /// What the Video frame box reads: the frame shown, or "none" where the take has no video frame.
  [[nodiscard]] QString videoFrameText() const;

signals:
  /// Opening the take restored `count` videos from its sidecar (`missing` of them not found).
  void videosRestored(int count, int missing);

private:
  struct Entry
  {
    ReferenceVideo* video = nullptr;
    VideoView* view = nullptr;
    ReferenceVideoLink stored;  // as the sidecar held it (kept as is while the file is missing)
  };

  void openDialog();
  void locateDialog();
  void restore();
  void takePathChanged(const QString& path);
  void clearEntries();
  /// Adds a video to the list (`opened`, or a new closed one) with the link the sidecar holds for it.
  int addEntry(const ReferenceVideoLink& link, ReferenceVideo* opened = nullptr);
  void updateInfo();
  void updateEvents();
  void scheduleSave();
  [[nodiscard]] std::vector<ReferenceVideoLink> links() const;
  void nudgeOrStep(int frames);

  TakeDocument& m_document;
  std::vector<Entry> m_entries;
  int m_current = -1;
  ReferenceVideo* m_none = nullptr;  // shown when the take has no video
  VideoView* m_noneView = nullptr;
  QStackedWidget* m_views = nullptr;
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
  // The sidecar: which take it belongs to, what it holds, and whether it may be written.
  QString m_sidecarTake;
  std::vector<ReferenceVideoLink> m_saved;
  bool m_sidecarReadable = true;  // a sidecar that could not be read is never overwritten
  bool m_restoring = false;
  QTimer m_saveTimer;
};

} // namespace mocap::ui
