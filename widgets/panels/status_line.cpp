#include "panels/status_line.h"

#include <QLabel>

namespace mocap::ui {

void showStatusLine(QLabel& line, const QString& text, bool error)
{
  line.setStyleSheet(error ? QStringLiteral("color: #d04040;") : QString());
  line.setText(text);
}

} // namespace mocap::ui
