#pragma once

#include <QString>

namespace mocap::ui {

/// The folder a panel's file dialogs open in: the one its last file was picked in, remembered in
/// QSettings as `group` + "folder" (e.g. "faceMesh/folder"), so each panel keeps its own.
[[nodiscard]] QString panelFolder(const QString& group);
/// Remembers the folder of `path` for `group`'s next dialog.
void rememberPanelFolder(const QString& group, const QString& path);

} // namespace mocap::ui
