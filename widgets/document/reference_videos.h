#pragma once

#include "mocap/video/reference_video_sidecar.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <vector>

namespace mocap::ui {

class ReferenceVideo;
class TakeDocument;

/// The open take's reference videos (one ReferenceVideo each, one of them current: only the
/// current one decodes) and their sidecar TAKE.video.json (see reference_video_sidecar.h): read
/// when a take is set, written a moment after each change (and when the take is saved under a new
/// name, beside the new file), so nudged offsets are written once. A video missing when the take
/// is opened stays linked as the sidecar holds it (locate() finds it) and nothing in the sidecar
/// is lost; a sidecar that cannot be read is never overwritten. Owned by the StudioSession; the
/// Reference Video dock only shows and edits it.
class ReferenceVideos final : public QObject
{
  Q_OBJECT

public:
  explicit ReferenceVideos(TakeDocument& document, QObject* parent = nullptr);
  /// Writes a pending change.
  ~ReferenceVideos() override;
  ReferenceVideos(const ReferenceVideos&) = delete;
  ReferenceVideos& operator=(const ReferenceVideos&) = delete;

  /// Links `path` to the take and makes it current (an already linked video only becomes
  /// current); returns "" or why it cannot be shown (nothing is added then).
  QString open(const QString& path);
  /// Unlinks video `index` from the take (and from its sidecar).
  void remove(int index);
  /// Opens `path` as missing video `index`, keeping its offset; returns "" or why it cannot be shown.
  QString locate(int index, const QString& path);

  [[nodiscard]] int count() const { return static_cast<int>(m_entries.size()); }
  [[nodiscard]] ReferenceVideo& at(int index) const;
  /// Whether video `index` was not found when the take was opened (or cannot be opened).
  [[nodiscard]] bool isMissing(int index) const;
  /// −1 when the take has no video.
  [[nodiscard]] int currentIndex() const { return m_current; }
  /// Makes video `index` current (out of range: the first, or none).
  void setCurrentIndex(int index);
  /// The current video, or nullptr when the take has none.
  [[nodiscard]] ReferenceVideo* current() const;

  /// Writes a pending change to the sidecar now.
  void save();

signals:
  /// Video `index` was linked (appended).
  void videoInserted(int index);
  /// Video `index` is about to be unlinked and deleted: nothing may refer to it after this.
  void videoAboutToBeRemoved(int index);
  /// Another video became current (or none, −1).
  void currentChanged(int index);
  /// Video `index` was opened or closed, its offset changed, or it showed a new frame.
  void videoChanged(int index);
  /// A take was set and its sidecar read: `count` videos, `missing` of them not found; `problem`
  /// is "" or why the sidecar could not be read.
  void restored(int count, int missing, const QString& problem);
  /// The sidecar could not be written.
  void saveFailed(const QString& error);

private:
  struct Entry
  {
    ReferenceVideo* video = nullptr;
    ReferenceVideoLink stored;  // as the sidecar held it (kept as is while the file is missing)
  };

  void restore();
  void takePathChanged(const QString& path);
  void clear();
  /// Appends a video (`opened`, or a new closed one) with the link the sidecar holds for it.
  int append(const ReferenceVideoLink& link, ReferenceVideo* opened = nullptr);
  /// Opens the video of a restored link; false when it is missing or cannot be opened.
  bool openRestored(ReferenceVideo& video, const ReferenceVideoLink& link);
  [[nodiscard]] int indexOf(const ReferenceVideo* video) const;
  [[nodiscard]] std::filesystem::path linkBase(const QString& video) const;
  void scheduleSave();
  [[nodiscard]] std::vector<ReferenceVideoLink> links() const;

  TakeDocument& m_document;
  std::vector<Entry> m_entries;
  int m_current = -1;
  // The sidecar: which take it belongs to, what it holds, and whether it may be written.
  QString m_sidecarTake;
  std::vector<ReferenceVideoLink> m_saved;
  bool m_sidecarReadable = true;
  bool m_restoring = false;
  QTimer m_saveTimer;
};

} // namespace mocap::ui
