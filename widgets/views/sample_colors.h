#pragma once

#include "mocap/take.h"

#include <QColor>

namespace mocap::ui {

/// The studio's colour for a sample state, shared by the 3D and curve views.
[[nodiscard]] QColor stateColor(SampleState state);
/// Highlight colour of selected markers.
[[nodiscard]] QColor selectionColor();

} // namespace mocap::ui
