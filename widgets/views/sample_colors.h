#pragma once

#include "mocap/model/take.h"

#include <QColor>

namespace mocap::ui {

/// The colours the views draw with, one per user preference.
struct ColorScheme
{
  QColor original{176, 196, 222};
  QColor filled{255, 153, 51};
  QColor smoothed{102, 204, 119};
  QColor edited{221, 102, 221};
  QColor selection{255, 230, 60};
  QColor flagged{255, 70, 70};  ///< bad points under review
  QColor background{31, 33, 38};  ///< the 3D view's (a gradient towards a lighter shade)

  friend bool operator==(const ColorScheme& a, const ColorScheme& b)
  {
    return a.original == b.original && a.filled == b.filled && a.smoothed == b.smoothed && a.edited == b.edited &&
           a.selection == b.selection && a.flagged == b.flagged && a.background == b.background;
  }
};

/// The scheme in use (application-wide, like QPalette); views redraw when told to.
[[nodiscard]] const ColorScheme& colorScheme();
void setColorScheme(const ColorScheme& scheme);

/// The studio's colour for a sample state, shared by the 3D and curve views.
[[nodiscard]] QColor stateColor(SampleState state);
/// Highlight colour of selected markers.
[[nodiscard]] QColor selectionColor();

} // namespace mocap::ui
