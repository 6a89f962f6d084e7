#pragma once

#include "document/layout_highlight.h"

#include <Eigen/Core>

#include <QColor>

namespace mocap::ui {

/// How the 3D view shows a planned layout (LayoutHighlight): markers kept (white, labelled) or
/// dropped (dim grey), and the head reference markers the plan leaves out (blue), drawn instead of
/// their sample state. The three are far apart in brightness and hue and none is a sample-state
/// colour (sample_colors.h) nor in the selection palette, so the layout reads at a glance and a
/// kept marker is never mistaken for a smoothed one.
[[nodiscard]] QColor layoutKeptColor();
/// The colour `marker` is drawn in under a non-empty `highlight`: kept, reference left out, or dropped.
[[nodiscard]] QColor layoutHighlightColor(const LayoutHighlight& highlight, Eigen::Index marker);

} // namespace mocap::ui
