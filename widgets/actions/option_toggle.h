#pragma once

#include "document/session_option.h"

class QAction;
class QMenu;

namespace mocap::ui {

/// A checkable action in `menu` that shows and sets `option`: checked as the option says, now and
/// whenever it changes, and toggling it sets the option (which is remembered and followed).
QAction* addOptionToggle(QMenu& menu, const QString& text, SessionOption<bool>& option);

} // namespace mocap::ui
