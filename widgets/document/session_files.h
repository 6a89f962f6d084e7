#pragma once

#include <QString>

namespace mocap::ui {

class StudioSession;

/// The files a session is made from on the command line (`mocap review`): the take and, when
/// given, a face mesh, a blendshape rig (a .glb/.gltf, or a neutral .obj/.ply with its shape
/// folder), the marker binding (made on the mesh, else on the rig's neutral) and whether to solve
/// the take to the rig's weights.
struct SessionFiles
{
  QString take;
  QString mesh;
  QString rig;
  QString rigShapes;
  QString binding;
  bool solve = false;
};

/// Loads `files` into `session` on the calling thread, as the studio's docks would: the take, the
/// mesh, the rig (its neutral becomes the face mesh unless the mesh has its vertex count), the
/// binding, then the solve with the Blendshape Solve dock's defaults (temporal, λ by GCV, the face
/// mesh's neutral frame and scale). For a program without a window; the studio runs these steps on
/// workers. Returns the first error (prefixed by the file it concerns; in the command line's terms,
/// English like mocap's other messages), or "". O(read + solve).
[[nodiscard]] QString loadSessionFiles(StudioSession& session, const SessionFiles& files);

} // namespace mocap::ui
