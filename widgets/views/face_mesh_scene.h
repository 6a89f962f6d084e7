#pragma once

#include "mocap/model/mesh.h"

#include <QObject>

#include <Eigen/Geometry>

#include <memory>
#include <optional>

class vtkRenderer;

namespace mocap::ui {

class DrawnPositions;
class FaceMeshModel;
class MeshLayer;
class ViewState;

/// How far along the mesh's x axis (mesh units) a second mesh is drawn beside it: a little more
/// than its width. O(#vertices).
[[nodiscard]] double sideOffset(const Mesh& mesh);

/// Mesh units → the coordinates the markers are drawn in (`markers`) for the document's current
/// frame: the model's meshToLab, in the markers' head-stabilized frame when they are drawn in one;
/// nullopt when the mesh cannot be placed. What the face mesh and the posed blendshape rig are both
/// placed by. O(1) (the head motion is cached by the document).
[[nodiscard]] std::optional<Eigen::Affine3d> meshPlacement(const FaceMeshModel& model, const DrawnPositions& markers);

/// The face mesh model (FaceMeshModel) drawn in a VTK renderer, with no widget: deforms the mesh
/// whenever the current frame or the rigs change, and places it where the markers are drawn
/// (`markers`: the lab frame or a head-stabilized frame alike). When comparing, the other method's
/// mesh is drawn offset beside the first along the mesh's x axis. Nothing here renders: changed()
/// asks the owner of the render window for a render, and updatePlacement() is to be called before
/// each (the markers' frame can change without a document signal). A frame costs the rigs' deform.
class FaceMeshScene final : public QObject
{
  Q_OBJECT

public:
  FaceMeshScene(FaceMeshModel& model, vtkRenderer* renderer, const DrawnPositions& markers, QObject* parent = nullptr);
  ~FaceMeshScene() override;

  [[nodiscard]] FaceMeshModel& model() const { return m_model; }
  [[nodiscard]] MeshLayer& layer() const { return *m_layer; }
  [[nodiscard]] MeshLayer& compareLayer() const { return *m_compareLayer; }
  /// Draws both meshes with `state`'s mesh look (opacity, edges) from now on, while both live.
  void observe(const ViewState& state);
  /// Where the mesh is drawn now (meshPlacement).
  [[nodiscard]] std::optional<Eigen::Affine3d> placement() const { return meshPlacement(m_model, m_markers); }
  /// Places the meshes where the markers are drawn now: call before each render.
  void updatePlacement();
  /// Milliseconds the last frame's deform took (−1 when it did not run).
  [[nodiscard]] double lastDeformMs() const { return m_deformMs; }
  [[nodiscard]] double lastCompareMs() const { return m_compareMs; }

signals:
  /// A frame was deformed; compareMilliseconds is −1 when not comparing.
  void deformed(double milliseconds, double compareMilliseconds);
  /// What is drawn changed: the renderer is due a render.
  void changed();

private:
  void showRestPose();
  void updateFrame();

  FaceMeshModel& m_model;
  const DrawnPositions& m_markers;
  std::unique_ptr<MeshLayer> m_layer;
  std::unique_ptr<MeshLayer> m_compareLayer;
  double m_deformMs = -1.0;
  double m_compareMs = -1.0;
  MeshVertices m_deformed;
};

} // namespace mocap::ui
