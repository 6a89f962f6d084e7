#pragma once

class QMenu;

namespace mocap::ui {

struct StudioOptions;
class ViewState;

/// The View menu's display options, each checked as its StudioOptions option says and setting it
/// (the session's ViewState, and so every view, follows the option): Reset Camera (Ctrl+R), Y or Z
/// Axis Up, Trails (on: at least 50 frames), Marker Links (L), Show Model Outputs, Follow Head (F).
void addViewOptionActions(QMenu& menu, StudioOptions& options, ViewState& view);

} // namespace mocap::ui
