#pragma once

#include <QObject>

#include <memory>

namespace mocap::ui {

class BlendshapeScene;
class FaceMeshScene;
class MarkerScene;
class StudioSession;
class ViewState;

/// What a session draws beside its markers, built from the session's models: the face mesh
/// (FaceMeshScene, from its FaceMeshModel) and the rig posed by the solved weights
/// (BlendshapeScene, from its BlendshapeSolveModel), in the markers' renderer, placed where the
/// markers are drawn. No widget: whoever composes the picture (the studio's main window for its 3D
/// view, ReviewScene for an off-screen review) makes one, renders on changed() and calls
/// beforeRender() before each render. Panels only observe it (the Face Mesh dock reads the deform
/// time and picks vertices on its layer). Made after the marker scene's layers, so the meshes
/// blend over the markers the same way in every picture.
class SessionScene final : public QObject
{
  Q_OBJECT

public:
  SessionScene(StudioSession& session, const MarkerScene& markers, QObject* parent = nullptr);
  ~SessionScene() override;

  [[nodiscard]] FaceMeshScene& faceMesh() const { return *m_faceMesh; }
  [[nodiscard]] BlendshapeScene& blendshapes() const { return *m_blendshapes; }
  /// The layers' look (face mesh opacity and edges, the posed rig shown and beside) as `state`
  /// says, from now on.
  void observe(const ViewState& state);
  /// Places the layers where the markers are drawn now (the head-stabilized frame can change
  /// without a document signal). Call before each render. O(1).
  void beforeRender();

signals:
  /// What is drawn changed: the renderer is due a render.
  void changed();

private:
  std::unique_ptr<FaceMeshScene> m_faceMesh;
  std::unique_ptr<BlendshapeScene> m_blendshapes;
};

} // namespace mocap::ui
