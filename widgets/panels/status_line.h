#pragma once

#include <QString>

class QLabel;

namespace mocap::ui {

/// Shows `text` in a panel's status line, in the error colour when `error` (a problem the user
/// must see, not a passing note).
void showStatusLine(QLabel& line, const QString& text, bool error);

} // namespace mocap::ui
