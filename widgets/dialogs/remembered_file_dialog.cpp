#include "dialogs/remembered_file_dialog.h"

#include "document/remembered_folder.h"

#include <QFileDialog>

namespace mocap::ui {

namespace {
QString remembered(const QString& group, QString path)
{
  if (!path.isEmpty())
    rememberFolder(group, path);
  return path;
}
} // namespace

QString openFileOfGroup(QWidget* parent, const QString& title, const QString& group, const QString& filter)
{
  return remembered(group, QFileDialog::getOpenFileName(parent, title, rememberedFolder(group), filter));
}

QString saveFileOfGroup(QWidget* parent, const QString& title, const QString& group, const QString& filter)
{
  return remembered(group, QFileDialog::getSaveFileName(parent, title, rememberedFolder(group), filter));
}

} // namespace mocap::ui
