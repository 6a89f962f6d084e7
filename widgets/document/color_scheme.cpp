#include "document/color_scheme.h"

namespace mocap::ui {

namespace {
ColorScheme& currentScheme()
{
  static ColorScheme scheme;
  return scheme;
}
} // namespace

const ColorScheme& colorScheme()
{
  return currentScheme();
}

void setColorScheme(const ColorScheme& scheme)
{
  currentScheme() = scheme;
}

} // namespace mocap::ui
