#pragma once

#include "document/session_option.h"

#include <QStringList>

class QMenu;
class QWidget;

namespace mocap::ui {

/// View ▸ Language: one checkable entry per language (`codes` with their `names`), the option's
/// language checked (`fallback` while it has none); choosing one sets the option and says that
/// it is used from the next start.
void addLanguageMenu(QMenu& menu, SessionOption<QString>& language, const QStringList& codes, const QStringList& names,
                     const QString& fallback, QWidget& dialogParent);

} // namespace mocap::ui
