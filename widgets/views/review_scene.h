#pragma once

#include "views/scene_settings.h"

#include <QImage>
#include <QSize>
#include <QString>

#include <Eigen/Core>

#include <memory>

namespace mocap::ui {

class AxesCorner;
class MarkerScene;
class OffscreenRenderWindow;
class SessionScene;
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

/// A session's scene rendered off screen frame by frame for a review video, with no widget and no
/// window: a private copy of the session (the take with the same selection, hidden and reference
/// markers, the face mesh, binding and rig options, the blendshape rig and weights) drawn as the
/// studio's 3D view draws it — its MarkerScene, the SessionScene's face mesh and posed rig layers
/// and the axes corner, in that order — into an OffscreenRenderWindow, as the source's settings
/// say. Stepping it never moves the studio's frame, and edits made in the studio meanwhile do not
/// reach it. Under X11 it needs a display (xvfb-run where there is none). UI thread only.
class ReviewScene
{
public:
  /// Copies `source` (which must have a session) to render at `size` (device pixels).
  ReviewScene(const ReviewSource& source, QSize size);
  ~ReviewScene();
  ReviewScene(const ReviewScene&) = delete;
  ReviewScene& operator=(const ReviewScene&) = delete;

  /// Whether the off-screen window has an OpenGL context; else why not.
  [[nodiscard]] bool usable() const;
  [[nodiscard]] QString failureReason() const;
  [[nodiscard]] const TakeDocument& document() const;

  /// Frames everything drawn over take frames first…last (MarkerScene::frameCamera, as Reset
  /// Camera does), so a moving head stays in the picture. O(#frames · #markers), at most 500
  /// frames sampled.
  void frameCamera(Eigen::Index first, Eigen::Index last);

  /// The picture at take frame `frame` (0-based), `size` pixels, RGB888. Null when not usable.
  /// O(one render).
  [[nodiscard]] QImage render(Eigen::Index frame);

private:
  void copySession(const StudioSession& source);
  /// The view's part of `settings` on the marker scene, the layers' look through the session's
  /// view state (which the layers observe, as the studio's do).
  void applySettings(const SceneSettings& settings);
  /// What goes before each render: the layers placed, the labels kept inside, the axes turned.
  void prepareRender();

  std::unique_ptr<StudioSession> m_session;
  std::unique_ptr<OffscreenRenderWindow> m_window;
  std::unique_ptr<MarkerScene> m_markers;
  std::unique_ptr<SessionScene> m_layers;
  std::unique_ptr<AxesCorner> m_axes;
};

} // namespace mocap::ui
