#pragma once

#include <QObject>
#include <QString>

class QMenu;
class QWidget;

namespace mocap::ui {

struct StudioOptions;
class TakeDocument;

/// The File menu's operations on the take: open (read on a worker, the open take kept when the
/// read fails), save (over the original only once confirmed), save as, export, the unsaved-edits
/// question, and Open Recent (the last eight files, remembered in StudioOptions::recentFiles).
class TakeFileActions final : public QObject
{
  Q_OBJECT

public:
  /// `dialogParent` parents the dialogs; `options` keeps the recent files and the last folder.
  TakeFileActions(TakeDocument& document, StudioOptions& options, QWidget& dialogParent, QObject* parent = nullptr);

  /// Opens `path`; on failure shows the error (unless `quiet`) and keeps the open take. Emits
  /// opened() on success. Returns the error message, empty on success ("Cancelled" when the read
  /// was cancelled).
  QString open(const QString& path, bool quiet = false);
  /// File ▸ Open…: the unsaved-edits question, then a file dialog, then open().
  void openWithDialog();
  /// File ▸ Save: over the file it came from, after asking once per take; no file: saveAs().
  bool save();
  /// File ▸ Save As…: asks for the file, saves, adds it to the recent files.
  bool saveAs();
  /// File ▸ Export…: asks for the file, then exportTo().
  void exportWithDialog();
  /// Writes a copy in the format of `path`'s extension; the take keeps its file. An .fbx opens
  /// the Export Animation dialog on FBX with `path` instead, so the file gets the up axis and key
  /// reduction `mocap convert --up --reduce` give, and the keys kept are reported.
  void exportTo(const QString& path);
  /// Asks to save unsaved edits: true when the caller may go on (saved or discarded).
  bool confirmDiscard();
  /// A recovered take has not been confirmed to overwrite its original.
  void forgetOverwriteConfirmation() { m_confirmedOverwrite = false; }
  /// Fills `menu` with the recent files now and whenever they change.
  void followRecentFiles(QMenu& menu);

signals:
  /// A file was opened; `askToAcknowledge`: data is missing or wrong and the open was not quiet.
  void opened(const QString& path, bool askToAcknowledge);
  /// What was saved or exported (and what the file leaves out), for the status bar.
  void message(const QString& text, int timeoutMs);

private:
  void addRecent(const QString& path);
  /// `text`, with what the file at `path` leaves out (leftOutOnWriting), if anything, shown longer.
  void showSaved(const QString& text, const QString& path);

  TakeDocument& m_document;
  StudioOptions& m_options;
  QWidget& m_dialogParent;
  bool m_confirmedOverwrite = false;
};

} // namespace mocap::ui
