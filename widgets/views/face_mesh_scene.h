#pragma once

#include "mocap/model/mesh.h"

#include <QObject>
#include <QPoint>
#include <QPointF>

#include <Eigen/Geometry>

#include <memory>
#include <optional>

namespace mocap::ui {

class FaceMeshModel;
class MarkerView3d;
class MeshLayer;
class ViewState;

/// How far along the mesh's x axis (mesh units) a second mesh is drawn beside it: a little more
/// than its width. O(#vertices).
[[nodiscard]] double sideOffset(const Mesh& mesh);

/// Mesh units → the coordinates `view` draws markers in for the document's current frame: the
/// model's meshToLab, in the view's head-stabilized frame when it has one; nullopt when the mesh
/// cannot be placed. What the face mesh and the posed blendshape rig are both placed by. O(1) (the
/// head motion is cached by the document).
[[nodiscard]] std::optional<Eigen::Affine3d> meshPlacement(const FaceMeshModel& model, const MarkerView3d& view);

/// The face mesh model (FaceMeshModel) drawn in the 3D view: deforms the mesh whenever the current
/// frame or the rigs change, and places it where the markers are drawn, in the lab frame or in the
/// view's head-stabilized frame alike. When comparing, the other method's mesh is drawn offset
/// beside the first along the mesh's x axis. A frame costs the rigs' deform.
class FaceMeshScene final : public QObject
{
  Q_OBJECT

public:
  FaceMeshScene(FaceMeshModel& model, MarkerView3d& view, QObject* parent = nullptr);
  ~FaceMeshScene() override;

  [[nodiscard]] FaceMeshModel& model() const { return m_model; }
  [[nodiscard]] MeshLayer& layer() const { return *m_layer; }
  [[nodiscard]] MeshLayer& compareLayer() const { return *m_compareLayer; }
  /// Draws both meshes with `state`'s mesh look (opacity, edges) from now on, while both live.
  void observe(const ViewState& state);
  /// The vertex of the (first) mesh under `position` (3D view widget coordinates), or −1.
  [[nodiscard]] Eigen::Index vertexAt(QPoint position) const;
  /// Where vertex `vertex` of the (first) mesh is drawn, in 3D view widget coordinates.
  [[nodiscard]] QPointF vertexPosition(Eigen::Index vertex) const;
  /// Where the mesh is drawn now (meshPlacement).
  [[nodiscard]] std::optional<Eigen::Affine3d> placement() const { return meshPlacement(m_model, m_view); }
  /// Milliseconds the last frame's deform took (−1 when it did not run).
  [[nodiscard]] double lastDeformMs() const { return m_deformMs; }
  [[nodiscard]] double lastCompareMs() const { return m_compareMs; }

signals:
  /// A frame was deformed; compareMilliseconds is −1 when not comparing.
  void deformed(double milliseconds, double compareMilliseconds);

private:
  void showRestPose();
  void updateFrame();
  void updatePlacement();

  FaceMeshModel& m_model;
  MarkerView3d& m_view;
  std::unique_ptr<MeshLayer> m_layer;
  std::unique_ptr<MeshLayer> m_compareLayer;
  double m_deformMs = -1.0;
  double m_compareMs = -1.0;
  MeshVertices m_deformed;
};

} // namespace mocap::ui
