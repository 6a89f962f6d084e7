#pragma once

#include <QDateTime>
#include <QObject>
#include <QString>
#include <QTimer>
#include <QVariantMap>

#include <functional>
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
  /// What the session provider gave at the time (face mesh, binding, window layout).
  QVariantMap session;
};

/// Writes the open take to a recovery file every `interval` while it has unsaved edits, so a
/// crash loses at most that much work, and removes the file once the take is saved, replaced or
/// closed cleanly. Writes are atomic (a crash during autosave leaves the previous recovery file).
/// One recovery file per process, in `folder` (the per-user application data folder by default).
/// The timer's writes run on a worker thread on a copy of the take (the C3D keeps sample states
/// and history); the description beside it also keeps what setSessionProvider() supplies.
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
  /// State besides the take that a recovery must bring back (the face mesh and its binding, the
  /// window layout): asked on the UI thread at every autosave and stored in the description.
  void setSessionProvider(std::function<QVariantMap()> provider) { m_session = std::move(provider); }
  /// Removes this process's recovery file (clean close, save).
  void discard();

  /// Recovery files left by other sessions in `folder` (default folder when empty), newest first.
  [[nodiscard]] static std::vector<RecoveryFile> leftovers(QString folder = {});
  /// Deletes a leftover recovery file and its description.
  static void remove(const RecoveryFile& file);
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
  JobRunner* m_write = nullptr;  // the background write
};

} // namespace mocap::ui
