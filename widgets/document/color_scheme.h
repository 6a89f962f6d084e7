#pragma once

#include <QColor>

namespace mocap::ui {

/// The colours the views draw with, one per user preference (a value: the session's ViewState
/// holds the one in use, StudioOptions remembers it).
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
  friend bool operator!=(const ColorScheme& a, const ColorScheme& b) { return !(a == b); }
};

/// The scheme in use (application-wide, like QPalette): what the views draw with. The session's
/// ViewState sets it; views redraw on its colorsChanged().
[[nodiscard]] const ColorScheme& colorScheme();
void setColorScheme(const ColorScheme& scheme);

} // namespace mocap::ui
