#include "views/sample_colors.h"

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

QColor stateColor(SampleState state)
{
  const ColorScheme& scheme = colorScheme();
  switch (state) {
  case SampleState::Original: return scheme.original;
  case SampleState::Filled: return scheme.filled;
  case SampleState::Smoothed: return scheme.smoothed;
  case SampleState::Edited: return scheme.edited;
  }
  return scheme.original;
}

QColor selectionColor()
{
  return colorScheme().selection;
}

} // namespace mocap::ui
