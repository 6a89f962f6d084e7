#include "views/selection_palette.h"

#include "views/sample_colors.h"

#include <algorithm>
#include <array>

namespace mocap::ui {

namespace {
// After the selection colour (yellow by default): sky blue, lime, pink, aqua, tan, violet, a
// pale grey. None is a sample-state colour (pale steel blue, orange, green, magenta, red) nor a
// layout-planning one (white, dim grey, royal blue).
constexpr std::array<QRgb, 7> kHues = {qRgb(90, 180, 255), qRgb(190, 240, 70), qRgb(255, 125, 190),
                                       qRgb(70, 225, 200), qRgb(215, 175, 125), qRgb(165, 135, 255),
                                       qRgb(200, 200, 200)};
} // namespace

std::size_t paletteSize()
{
  return kHues.size() + 1;
}

QColor selectionPaletteColor(std::size_t index)
{
  index %= paletteSize();
  return index == 0 ? colorScheme().selection : QColor::fromRgb(kHues[index - 1]);
}

QColor selectedMarkerColor(const std::vector<Eigen::Index>& selection, Eigen::Index marker)
{
  const auto it = std::lower_bound(selection.begin(), selection.end(), marker);
  if (it == selection.end() || *it != marker)
    return {};
  return selectionPaletteColor(static_cast<std::size_t>(it - selection.begin()));
}

} // namespace mocap::ui
