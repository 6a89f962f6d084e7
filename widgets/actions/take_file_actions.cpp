#include "actions/take_file_actions.h"

#include "dialogs/export_dialog.h"
#include "dialogs/job_dialog.h"
#include "document/studio_options.h"
#include "document/take_document.h"
#include "views/status_timeout.h"

#include "mocap/io/take_io.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>

#include <string>
#include <utility>

namespace mocap::ui {

namespace {
constexpr int kMaxRecent = 8;
} // namespace

TakeFileActions::TakeFileActions(TakeDocument& document, StudioOptions& options, QWidget& dialogParent, QObject* parent)
    : QObject(parent), m_document(document), m_options(options), m_dialogParent(dialogParent)
{
}

QString TakeFileActions::open(const QString& path, bool quiet)
{
  // Read on a worker (a long take takes seconds); the UI thread only installs the result.
  TakeDocument::ReadResult read;
  QString error;
  try {
    if (!runJob(&m_dialogParent, tr("Opening %1…").arg(QFileInfo(path).fileName()),
                [&](const JobControl&) { read = TakeDocument::read(path); }))
      return tr("Cancelled");
    m_document.open(std::move(read), path);
  } catch (const std::exception& e) {  // a failed read leaves the open take as it was
    error = QString::fromStdString(e.what());
  }
  if (!error.isEmpty()) {
    if (!quiet)
      QMessageBox::critical(&m_dialogParent, tr("Cannot open file"), error);
    return error;
  }
  m_confirmedOverwrite = false;
  addRecent(path);
  m_options.lastFolder = QFileInfo(path).absolutePath();
  emit opened(path, !quiet && m_document.hasDataLoss());
  return {};
}

void TakeFileActions::openWithDialog()
{
  if (!confirmDiscard())
    return;
  const QString path = QFileDialog::getOpenFileName(&m_dialogParent, tr("Open take"), m_options.lastFolder,
                                                    tr("Motion capture (*.c3d *.trc);;All files (*)"));
  if (!path.isEmpty())
    open(path);
}

bool TakeFileActions::save()
{
  const QString path = m_document.filePath();
  if (path.isEmpty())
    return saveAs();
  if (!m_confirmedOverwrite) {
    const auto answer = QMessageBox::question(
        &m_dialogParent, tr("Overwrite the original?"),
        tr("Save over %1? The original capture is replaced by the edited take.").arg(QFileInfo(path).fileName()),
        QMessageBox::Save | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer != QMessageBox::Save)
      return false;
    m_confirmedOverwrite = true;
  }
  const QString error = m_document.save(path);
  if (!error.isEmpty())
    QMessageBox::critical(&m_dialogParent, tr("Cannot save"), error);
  return error.isEmpty();
}

bool TakeFileActions::saveAs()
{
  const QString path = QFileDialog::getSaveFileName(&m_dialogParent, tr("Save take as"), m_document.filePath(),
                                                    tr("C3D (*.c3d);;TRC (*.trc)"));
  if (path.isEmpty())
    return false;
  const QString error = m_document.save(path);
  if (!error.isEmpty()) {
    QMessageBox::critical(&m_dialogParent, tr("Cannot save"), error);
    return false;
  }
  m_confirmedOverwrite = true;  // the user chose this file
  addRecent(path);
  showSaved(tr("Saved %1").arg(path), path);
  return true;
}

void TakeFileActions::exportWithDialog()
{
  const QString path =
      QFileDialog::getSaveFileName(&m_dialogParent, tr("Export"), QFileInfo(m_document.filePath()).absolutePath(),
                                   tr("C3D (*.c3d);;TRC (*.trc);;CSV (*.csv);;BVH (*.bvh);;FBX markers (*.fbx)"));
  if (!path.isEmpty())
    exportTo(path);
}

void TakeFileActions::exportTo(const QString& path)
{
  if (QFileInfo(path).suffix().compare(QStringLiteral("fbx"), Qt::CaseInsensitive) == 0) {
    ExportDialog dialog(m_document, &m_dialogParent);
    dialog.setFormat(AnimationFormat::Fbx);
    dialog.setOutputPath(path);
    dialog.exec();  // it says what it wrote and the keys it kept
    return;
  }
  const QString error = m_document.save(path, false);
  if (!error.isEmpty())
    QMessageBox::critical(&m_dialogParent, tr("Cannot export"), error);
  else
    showSaved(tr("Exported %1").arg(path), path);
}

void TakeFileActions::showSaved(const QString& text, const QString& path)
{
  const std::string leftOut = leftOutOnWriting(m_document.take(), formatFromPath(path.toStdString()));
  if (leftOut.empty())
    emit message(text, kStatusMessageMs);
  else  // data the file does not hold: shown longer, and not only in passing
    emit message(tr("%1 — note: %2").arg(text, QString::fromStdString(leftOut)), 3 * kStatusMessageMs);
}

bool TakeFileActions::confirmDiscard()
{
  if (!m_document.isModified())
    return true;
  const auto answer =
      QMessageBox::warning(&m_dialogParent, tr("Unsaved edits"), tr("The take has unsaved edits. Save them?"),
                           QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
  if (answer == QMessageBox::Save)
    return save();
  return answer == QMessageBox::Discard;
}

void TakeFileActions::addRecent(const QString& path)
{
  QStringList recent = m_options.recentFiles;
  const QString absolute = QFileInfo(path).absoluteFilePath();
  recent.removeAll(absolute);
  recent.prepend(absolute);
  while (recent.size() > kMaxRecent)
    recent.removeLast();
  m_options.recentFiles = recent;
}

void TakeFileActions::followRecentFiles(QMenu& menu)
{
  m_options.recentFiles.follow(&menu, [this, &menu](const QStringList& recent) {
    menu.clear();
    for (const QString& path : recent)
      menu.addAction(QFileInfo(path).fileName(), this, [this, path] {
            if (confirmDiscard())
              open(path);
          })->setToolTip(path);
    menu.setEnabled(!recent.isEmpty());
  });
}

} // namespace mocap::ui
