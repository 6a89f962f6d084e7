#pragma once

#include "document/blendshape_solve_model.h"
#include "document/layout_plan_model.h"

#include "mocap/deform/actor_profile.h"
#include "mocap/deform/blendshape_solver.h"
#include "mocap/model/retarget_map.h"

#include <QByteArray>
#include <QString>

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mocap::ui {

/// A reference video of the session: its file and its offset (video time at the take's first frame).
struct SessionVideo
{
  QString path;
  double offset = 0.0;
};

/// What a StudioSession holds beside its take, as a value: the take itself (samples, states,
/// history, head reference markers) is kept in its own file format. Files are kept by name (the
/// face mesh, the blendshape rig, the videos: read again when restored); what was made in the
/// session is kept whole (the binding with its edits, the weight curves with their edits, how
/// they were solved, the actor profile, the Retarget section's map with its edited gains, the
/// layout plan with its picked size). StudioSession::saveState() copies it
/// on the UI thread; encoding and decoding run on any thread; StudioSession::restoreState() brings
/// it back (crash recovery).
struct SessionState
{
  QString meshPath;     ///< the face mesh's file; "" without one
  std::string binding;  ///< its binding as bindingJson writes it
  QString rigPath;      ///< the blendshape rig's file (a .glb/.gltf, or a neutral .obj); "" without one
  QString rigShapeFolder;  ///< an OBJ rig's folder of shapes
  /// The weight curves as they are (edits included) and how they were solved; no rows when none.
  BlendshapeSolveResult curves;
  BlendshapeSolveOptions solvedWith;  ///< with the actor profile they were solved with, if any
  std::optional<ReadWeightCurves> readCurves;  ///< set when the curves were read from a recording
  std::vector<Eigen::Index> selectedShapes;
  std::vector<SessionVideo> videos;
  int currentVideo = -1;
  /// The last layout plan (shared: the model's is never changed) and the marker count picked.
  std::shared_ptr<const LayoutPlanResult> layoutPlan;
  Eigen::Index layoutSize = 0;
  /// The actor profile the solve uses (kept whole: its file may have been calibrated again since)
  /// and the file it was read from; none without one. Since version 2.
  std::shared_ptr<const ActorProfile> actor;
  QString actorPath;
  /// The Retarget section's map with its gains as edited, what it was read from (a shipped name or
  /// a path) and whether a gain was changed since it was read or saved. Since version 2.
  std::optional<RetargetMap> retargetMap;
  QString retargetMapName;
  bool retargetMapEdited = false;
};

/// The state as bytes (a versioned binary format of this program's own). O(size of the state).
[[nodiscard]] QByteArray encodeSessionState(const SessionState& state);
/// The state from encodeSessionState's bytes, of this version or an earlier one (version 1 has no
/// actor and no retarget map: those stay empty). Throws FormatError (naming `source`) for bytes
/// that are not a session state, of a later version, cut short or inconsistent. O(size).
[[nodiscard]] SessionState decodeSessionState(const QByteArray& bytes, const std::string& source);

} // namespace mocap::ui
