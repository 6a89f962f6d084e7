#include "views/sample_colors.h"

namespace mocap::ui {

QColor stateColor(SampleState state)
{
  switch (state) {
  case SampleState::Original: return {176, 196, 222};
  case SampleState::Filled: return {255, 153, 51};
  case SampleState::Smoothed: return {102, 204, 119};
  case SampleState::Edited: return {221, 102, 221};
  }
  return {176, 196, 222};
}

QColor selectionColor()
{
  return {255, 230, 60};
}

} // namespace mocap::ui
