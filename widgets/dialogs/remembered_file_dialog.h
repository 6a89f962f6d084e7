#pragma once

#include <QString>

class QWidget;

namespace mocap::ui {

/// A file to open, asked for in the folder `group`'s dialogs remember (rememberedFolder, e.g.
/// "faceMesh/"); the folder of the file picked is remembered for the group's next dialog. Empty
/// when declined.
[[nodiscard]] QString openFileOfGroup(QWidget* parent, const QString& title, const QString& group,
                                      const QString& filter);
/// The same for a file to save (the dialog asks before replacing one).
[[nodiscard]] QString saveFileOfGroup(QWidget* parent, const QString& title, const QString& group,
                                      const QString& filter);

} // namespace mocap::ui
