#pragma once

#include "views/scene_settings.h"

#include <QImage>
#include <QSize>

#include <Eigen/Core>

#include <memory>

class QWidget;

namespace mocap::ui {

class BlendshapeScene;
class FaceMeshScene;
class MarkerView3d;
class StudioSession;
class TakeDocument;

/// What a review video draws: a session (the take with its selection, hidden markers and
/// reference markers, the face mesh with its binding, the blendshape rig with its weights) drawn
/// with `settings` (the 3D view's settings, the mesh look, the camera when the studio's is to be
/// kept). Built by the studio from its session and views, by `mocap review` from files alone.
struct ReviewSource
{
  const StudioSession* session = nullptr;
  SceneSettings settings;
  /// Frame the reviewed frames afresh (ReviewScene::frameCamera) instead of the settings' camera.
  bool resetCamera = false;
};

/// A session's scene rendered off screen frame by frame for a review video, with no studio window:
/// a private copy of the session (the take with the same selection, hidden and reference markers,
/// the face mesh, binding and rig options, the blendshape rig and weights) drawn by its own 3D view
/// with the face mesh and posed rig layers the studio draws (FaceMeshScene, BlendshapeScene), as
/// the source's settings say. Stepping it never moves the studio's frame, and edits made in the
/// studio meanwhile do not reach it. The view lives in a top-level widget that is never shown on
/// screen (Qt::WA_DontShowOnScreen): it needs a GL context but no visible window, under X11 a
/// display (xvfb-run where there is none). UI thread only.
class ReviewScene
{
public:
  /// Copies `source` (which must have a session) to render at `size` (device pixels).
  ReviewScene(const ReviewSource& source, QSize size);
  ~ReviewScene();
  ReviewScene(const ReviewScene&) = delete;
  ReviewScene& operator=(const ReviewScene&) = delete;

  /// Whether the view has a GL context; else why not.
  [[nodiscard]] bool usable() const;
  [[nodiscard]] QString failureReason() const;
  [[nodiscard]] const TakeDocument& document() const;
  [[nodiscard]] MarkerView3d& view() const { return *m_view; }

  /// Frames everything drawn over take frames first…last (MarkerView3d::frameCamera), so a moving
  /// head stays in the picture. O(#frames · #markers), at most 500 frames sampled.
  void frameCamera(Eigen::Index first, Eigen::Index last);

  /// The view at take frame `frame` (0-based), `size` pixels, RGB. Null when the view is not usable.
  /// O(one render).
  [[nodiscard]] QImage render(Eigen::Index frame);

private:
  void copySession(const StudioSession& source);

  std::unique_ptr<StudioSession> m_session;
  std::unique_ptr<QWidget> m_window;
  MarkerView3d* m_view = nullptr;  // owned by m_window
  std::unique_ptr<FaceMeshScene> m_faceMesh;
  std::unique_ptr<BlendshapeScene> m_blendshapes;
  QSize m_size;
};

} // namespace mocap::ui
