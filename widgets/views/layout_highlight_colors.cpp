#include "views/layout_highlight_colors.h"

namespace mocap::ui {

QColor layoutKeptColor()
{
  return {250, 250, 250};
}

QColor layoutHighlightColor(const LayoutHighlight& highlight, Eigen::Index marker)
{
  const auto i = static_cast<std::size_t>(marker);
  if (highlight.kept[i])
    return layoutKeptColor();
  return !highlight.reference.empty() && highlight.reference[i] ? QColor(40, 110, 255) : QColor(85, 85, 92);
}

} // namespace mocap::ui
