#pragma once

class QWidget;

namespace mocap::ui {

class StudioSession;

/// File ▸ Export Animation…: the markers as BVH and, when the session's face mesh has a rig,
/// the mesh deformed by the take (on a worker thread, with a deformer of its own); a rig that
/// cannot be copied is reported and the markers still export.
void exportAnimation(const StudioSession& session, QWidget& dialogParent);

} // namespace mocap::ui
