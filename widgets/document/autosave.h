#pragma once

#include "document/session_state.h"

#include <QDateTime>
#include <QObject>
#include <QString>
#include <QTimer>
#include <QVariantMap>

#include <functional>
#include <optional>
#include <vector>

namespace mocap::ui {

class JobRunner;
class TakeDocument;

/// A take written by Autosave that its session never saved or closed cleanly (a crash, a kill,
/// a power cut): where it is, which file it was editing and when it was written.
struct RecoveryFile
{
  QString path;          ///< the recovery C3D
  QString originalPath;  ///< the file the edits were made to (empty for an untitled take)
  QDateTime written;
  /// What the session provider gave at the time (the window layout).
  QVariantMap session;
  /// The session's state beside the take (Autosave::readState reads it); "" when none was written.
  QString statePath;
};

/// Writes the open take to a recovery file every `interval` while it has unsaved edits, so a
/// crash loses at most that much work, and removes the file once the take is saved, replaced or
/// closed cleanly. Writes are atomic (a crash during autosave leaves the previous recovery file).
/// One recovery file per process, in `folder` (the per-user application data folder by default).
/// The timer's writes run on a worker thread on a copy of the take (the C3D keeps sample states,
/// history and the head reference markers) and of the session's state (setStateProvider: face
/// mesh, binding, rig and weights, videos, layout plan), written beside it; the description beside
/// them keeps what setSessionProvider() supplies.
class Autosave final : public QObject
{
  Q_OBJECT

public:
  explicit Autosave(TakeDocument& document, QString folder = {}, QObject* parent = nullptr);
  ~Autosave() override;

  void setInterval(int milliseconds);
  [[nodiscard]] int interval() const { return m_timer.interval(); }
  [[nodiscard]] const QString& folder() const { return m_folder; }
  /// The recovery file of this process (may not exist yet).
  [[nodiscard]] QString recoveryPath() const;

  /// Writes the recovery file now if the take has unsaved edits, waiting for it. Returns an
  /// error message or an empty string.
  QString saveNow();
  /// Starts writing the recovery file on a worker thread (what the timer does); the UI thread
  /// only copies the take. A write still running is not started twice. Errors come as failed().
  void saveInBackground();
  /// Blocks until a background write has finished and handles its outcome at once (no event
  /// loop). Before a write or removal of the recovery file, and at shutdown.
  void waitForWrite();
  /// What the window shows besides the session (its layout): asked on the UI thread at every
  /// autosave and stored in the description.
  void setSessionProvider(std::function<QVariantMap()> provider) { m_session = std::move(provider); }
  /// The session's state beside the take (StudioSession::saveState): asked on the UI thread at
  /// every autosave (a copy), encoded and written on the worker with the take.
  void setStateProvider(std::function<SessionState()> provider) { m_state = std::move(provider); }
  /// Removes this process's recovery file (clean close, save).
  void discard();

  /// Recovery files left by other sessions in `folder` (default folder when empty), newest first.
  [[nodiscard]] static std::vector<RecoveryFile> leftovers(QString folder = {});
  /// Deletes a leftover recovery file, its description and its session state.
  static void remove(const RecoveryFile& file);
  /// The session state kept with a leftover, or none when it has none. A leftover of a studio from
  /// before session states has its face mesh and binding in its description: they come back as a
  /// state of that much. Throws IoError or FormatError for a state that cannot be read.
  [[nodiscard]] static std::optional<SessionState> readState(const RecoveryFile& file);
  [[nodiscard]] static QString defaultFolder();

signals:
  /// Autosave failed (disk full, folder not writable): the message says why.
  void failed(const QString& message);
  /// A background write finished successfully.
  void written();

private:
  /// Creates the folder and writes the description; returns an error or "".
  QString prepare();
  void onWriteFinished(const QString& error);

  TakeDocument& m_document;
  QString m_folder;
  QTimer m_timer;
  std::function<QVariantMap()> m_session;
  std::function<SessionState()> m_state;
  JobRunner* m_write = nullptr;  // the background write
};

} // namespace mocap::ui
