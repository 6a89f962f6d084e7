#include "document/remembered_folder.h"

#include "document/session_option.h"

#include <QFileInfo>

namespace mocap::ui {

namespace {
QString folderKey(const QString& group)
{
  return group + QStringLiteral("folder");
}
} // namespace

QString rememberedFolder(const QString& group)
{
  return SessionOption<QString>(folderKey(group), QString()).get();
}

void rememberFolder(const QString& group, const QString& path)
{
  SessionOption<QString>(folderKey(group), QString()).set(QFileInfo(path).absolutePath());
}

} // namespace mocap::ui
