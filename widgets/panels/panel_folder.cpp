#include "panels/panel_folder.h"

#include <QFileInfo>
#include <QSettings>

namespace mocap::ui {

QString panelFolder(const QString& group)
{
  return QSettings().value(group + QStringLiteral("folder")).toString();
}

void rememberPanelFolder(const QString& group, const QString& path)
{
  QSettings().setValue(group + QStringLiteral("folder"), QFileInfo(path).absolutePath());
}

} // namespace mocap::ui
