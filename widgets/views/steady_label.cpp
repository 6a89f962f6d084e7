#include "views/steady_label.h"

#include <QLabel>

#include <algorithm>

namespace mocap::ui {

void fixLabelSizeFor(QLabel& label, const QString& widest, int minimumWidth)
{
  constexpr int kPadding = 8;  // the frame and margins around the text
  const int width = std::max(minimumWidth, label.fontMetrics().horizontalAdvance(widest) + kPadding);
  label.setFixedSize(width, label.sizeHint().height());
}

} // namespace mocap::ui
