#pragma once

#include <QImage>
#include <QSize>

#include <Eigen/Core>

#include <memory>

class QWidget;

namespace mocap::ui {

class BlendshapeScene;
class BlendshapeSolveModel;
class FaceMeshModel;
class FaceMeshScene;
class MarkerView3d;
class TakeDocument;

/// What the studio shows that a review video draws: the 3D view (its take, selection, hidden
/// markers, trails, head-stabilized or followed view, camera), and optionally the face mesh scene
/// and the posed blendshape rig. Only the 3D view is required.
struct ReviewSource
{
  const TakeDocument* document = nullptr;
  const MarkerView3d* view = nullptr;
  const FaceMeshScene* faceMesh = nullptr;
  const BlendshapeScene* blendshapes = nullptr;
  /// Frame the reviewed frames afresh (ReviewScene::frameCamera) instead of keeping the view's
  /// camera (the command line, whose view was never shown).
  bool resetCamera = false;
};

/// A private copy of the studio's 3D view, rendered off screen frame by frame for a review video:
/// its own document (a copy of the take with the same selection and hidden markers), 3D view with
/// the same settings and camera, and, when the source has them, its own face mesh model and rig
/// with the same mesh, binding, options, rig and weights. Stepping it never moves the studio's
/// frame, and edits made in the studio meanwhile do not reach it. The view lives in a top-level
/// widget that is never shown on screen (Qt::WA_DontShowOnScreen), so it needs a GL context but
/// no visible window: under X11 a display (xvfb-run where there is none). UI thread only.
class ReviewScene
{
public:
  /// Copies `source` (which must have a document and a view) to render at `size` (device pixels).
  ReviewScene(const ReviewSource& source, QSize size);
  ~ReviewScene();
  ReviewScene(const ReviewScene&) = delete;
  ReviewScene& operator=(const ReviewScene&) = delete;

  /// Whether the view has a GL context; else why not.
  [[nodiscard]] bool usable() const;
  [[nodiscard]] QString failureReason() const;
  [[nodiscard]] const TakeDocument& document() const { return *m_document; }
  [[nodiscard]] MarkerView3d& view() const { return *m_view; }

  /// Frames the camera on every marker drawn over take frames first…last (in the studio's viewing
  /// direction), so a moving head stays in the picture. O(#frames · #markers), at most 500 frames
  /// sampled.
  void frameCamera(Eigen::Index first, Eigen::Index last);

  /// The view at take frame `frame` (0-based), `size` pixels, RGB. Null when the view is not usable.
  /// O(one render).
  [[nodiscard]] QImage render(Eigen::Index frame);

private:
  void copyFaceMesh(const FaceMeshScene& source);
  void copyBlendshapes(const BlendshapeScene& source);

  std::unique_ptr<QWidget> m_window;
  std::unique_ptr<TakeDocument> m_document;
  MarkerView3d* m_view = nullptr;  // owned by m_window
  std::unique_ptr<FaceMeshModel> m_faceMeshModel;
  std::unique_ptr<FaceMeshScene> m_faceMesh;
  std::unique_ptr<BlendshapeSolveModel> m_blendshapeModel;
  std::unique_ptr<BlendshapeScene> m_blendshapes;
  QSize m_size;
};

} // namespace mocap::ui
