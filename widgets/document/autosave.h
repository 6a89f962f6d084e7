#pragma once

#include <QDateTime>
#include <QObject>
#include <QString>
#include <QTimer>

#include <vector>

namespace mocap::ui {

class TakeDocument;

/// A take written by Autosave that its session never saved or closed cleanly (a crash, a kill,
/// a power cut): where it is, which file it was editing and when it was written.
struct RecoveryFile
{
  QString path;          ///< the recovery C3D
  QString originalPath;  ///< the file the edits were made to (empty for an untitled take)
  QDateTime written;
};

/// Writes the open take to a recovery file every `interval` while it has unsaved edits, so a
/// crash loses at most that much work, and removes the file once the take is saved, replaced or
/// closed cleanly. Writes are atomic (a crash during autosave leaves the previous recovery file).
/// One recovery file per process, in `folder` (the per-user application data folder by default).
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

  /// Writes the recovery file now if the take has unsaved edits. Returns an error message or an
  /// empty string.
  QString saveNow();
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

private:
  TakeDocument& m_document;
  QString m_folder;
  QTimer m_timer;
};

} // namespace mocap::ui
