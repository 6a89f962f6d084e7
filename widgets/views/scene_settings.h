#pragma once

#include <QSize>

#include <Eigen/Core>

#include <optional>
#include <vector>

class vtkCamera;

namespace mocap::ui {

class MarkerScene;
class MarkerView3d;
class ViewState;

/// A camera as a value: where it is, what it looks at, and the size of the view it was set for.
struct CameraState
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d focalPoint = Eigen::Vector3d::Zero();
  Eigen::Vector3d viewUp = Eigen::Vector3d::UnitZ();
  double viewAngle = 30.0;  // degrees, vertical
  QSize viewSize;           // logical pixels of the view it was set for
};

[[nodiscard]] CameraState cameraState(vtkCamera& camera, QSize viewSize);
/// Sets `camera` to `state` for a view of `viewSize`: the same view, widened when the view is
/// narrower than the state's (VTK keeps the vertical angle, so a narrower view would crop the sides).
void applyCameraState(const CameraState& state, vtkCamera& camera, QSize viewSize);

/// How the studio draws a session's scene beyond what the session's models hold: the 3D view's
/// settings, the mesh layers' look and, optionally, the camera. A plain value: a review video is
/// built from a session and these, never from the studio's widgets. The defaults are the studio's
/// first-run ones.
struct SceneSettings
{
  int upAxis = 2;
  int trailFrames = 50;
  double markerScale = 0.012;
  bool linksVisible = false;
  std::vector<Eigen::Index> headReference;  // empty: the lab frame
  bool followHead = false;
  std::vector<bool> layoutKept;  // empty: no layout highlight
  std::vector<bool> layoutReference;
  double meshOpacity = 0.6;  // the face mesh and its compared mesh (MeshLayer's default)
  bool meshEdges = false;
  bool rigShown = true;  // the posed blendshape rig (BlendshapeScene)
  bool rigBeside = true;
  std::optional<CameraState> camera;  // none: framed on what is drawn
};

/// The 3D view's part of the settings (view settings and camera; the mesh look stays default).
[[nodiscard]] SceneSettings viewSettings(const MarkerView3d& view);
/// What the studio shows now: the 3D view's part (viewSettings) with the layers' look (face mesh
/// opacity and edges, the posed rig shown and beside) from the session's view state.
[[nodiscard]] SceneSettings shownSettings(const MarkerView3d& view, const ViewState& state);
/// Draws `markers` with the 3D view's part of `settings`, sized to the take and drawn at its
/// current frame, with the settings' camera (for a view of `viewSize`) when they have one.
void applyViewSettings(const SceneSettings& settings, MarkerScene& markers, QSize viewSize);

} // namespace mocap::ui
