#pragma once

#include "mocap/model/mesh.h"

#include <QObject>

#include <memory>

class vtkRenderer;

namespace mocap::ui {

class BlendshapeSolveModel;
class DrawnPositions;
class FaceMeshModel;
class MeshLayer;
class ViewState;

/// The blendshape rig posed by the solved weights (BlendshapeSolveModel) drawn in a VTK renderer,
/// with no widget, placed as the face mesh is (meshPlacement: the binding's alignment, on the
/// captured head, where `markers` are drawn), over the markers or beside them (on the side away
/// from the compared mesh). Hidden without a solve or when switched off. As FaceMeshScene:
/// changed() asks for a render, updatePlacement() goes before each. A frame costs the rig's
/// evaluate, O(#vertices + Σ #moved).
class BlendshapeScene final : public QObject
{
  Q_OBJECT

public:
  BlendshapeScene(BlendshapeSolveModel& model, FaceMeshModel& faceMesh, vtkRenderer* renderer,
                  const DrawnPositions& markers, QObject* parent = nullptr);
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
  /// Places the posed rig where the markers are drawn now: call before each render.
  void updatePlacement();

signals:
  /// What is drawn changed: the renderer is due a render.
  void changed();

private:
  void updateMesh();
  void updateFrame();

  BlendshapeSolveModel& m_model;
  FaceMeshModel& m_faceMesh;
  const DrawnPositions& m_markers;
  std::unique_ptr<MeshLayer> m_layer;
  MeshVertices m_posed;
  bool m_shown = true;
  bool m_posedShown = false;  // posed at the current frame (a solve, a rig, switched on)
  bool m_beside = false;
};

} // namespace mocap::ui
