#pragma once

#include <QString>

namespace mocap::ui {

/// The folder a file dialog opens in: the one its last file was picked in, remembered as the
/// session option `group` + "folder" (e.g. "faceMesh/folder"), so each panel and dialog keeps its own.
/// Empty when none is remembered (the caller's fallback then applies).
[[nodiscard]] QString rememberedFolder(const QString& group);
/// Remembers the folder of `path` for `group`'s next dialog.
void rememberFolder(const QString& group, const QString& path);

} // namespace mocap::ui
