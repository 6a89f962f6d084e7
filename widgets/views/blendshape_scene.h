#pragma once

#include "mocap/model/mesh.h"

#include <QObject>

#include <memory>

namespace mocap::ui {

class BlendshapeSolveModel;
class FaceMeshModel;
class MarkerView3d;
class MeshLayer;
class ViewState;

/// The blendshape rig posed by the solved weights (BlendshapeSolveModel) in the 3D view, placed
/// as the face mesh is (meshPlacement: the binding's alignment, on the captured head),
/// over the markers or beside them (on the side away from the compared mesh). Hidden without a
/// solve or when switched off. A frame costs the rig's evaluate, O(#vertices + Σ #moved).
class BlendshapeScene final : public QObject
{
  Q_OBJECT

public:
  BlendshapeScene(BlendshapeSolveModel& model, FaceMeshModel& faceMesh, MarkerView3d& view,
                  QObject* parent = nullptr);
  ~BlendshapeScene() override;

  [[nodiscard]] BlendshapeSolveModel& model() const { return m_model; }
  void setShown(bool shown);
  [[nodiscard]] bool shown() const { return m_shown; }
  /// Beside the markers instead of over them.
  void setBeside(bool beside);
  [[nodiscard]] bool beside() const { return m_beside; }
  /// Shown and beside as `state` says (rigShown, rigBeside) from now on, while both live.
  void observe(const ViewState& state);
  [[nodiscard]] MeshLayer& layer() const { return *m_layer; }

private:
  void updateMesh();
  void updateFrame();
  void updatePlacement();

  BlendshapeSolveModel& m_model;
  FaceMeshModel& m_faceMesh;
  MarkerView3d& m_view;
  std::unique_ptr<MeshLayer> m_layer;
  MeshVertices m_posed;
  bool m_shown = true;
  bool m_posedShown = false;  // posed at the current frame (a solve, a rig, switched on)
  bool m_beside = false;
};

} // namespace mocap::ui
