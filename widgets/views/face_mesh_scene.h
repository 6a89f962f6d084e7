#pragma once

#include "mocap/deform/face_rig.h"
#include "mocap/cleaning/head_stabilization.h"
#include "mocap/model/mesh.h"
#include "mocap/deform/mesh_binding.h"

#include <QObject>
#include <QPoint>
#include <QPointF>
#include <QString>

#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mocap::ui {

class MarkerView3d;
class MeshLayer;
class TakeDocument;

/// A face mesh in the 3D view, driven by the open take: holds the mesh, its marker binding and
/// the rig settings, keeps a FaceRig (and, when comparing, a second rig with the other method,
/// drawn beside the first) set up for the take, and deforms the mesh whenever the current frame
/// changes. Head stabilization: when reference labels are given, the rigs see a copy of the take
/// with head motion removed (the frame bindings are made in), and the mesh is put back on the
/// head each frame, so it lines up with the markers in the lab frame and in the view's
/// head-stabilized frame alike. Rig set-up is synchronous (a few milliseconds for a face of
/// hundreds of vertices); a frame costs the rigs' deform (O(#vertices · #controls)).
class FaceMeshScene final : public QObject
{
  Q_OBJECT

public:
  FaceMeshScene(TakeDocument& document, MarkerView3d& view, QObject* parent = nullptr);
  ~FaceMeshScene() override;

  /// Replaces the mesh; a binding made for another vertex count is dropped.
  void setMesh(Mesh mesh);
  [[nodiscard]] const Mesh& mesh() const { return m_mesh; }
  [[nodiscard]] bool hasMesh() const { return m_mesh.vertexCount() > 0; }
  void setBinding(MeshBinding binding);
  [[nodiscard]] const MeshBinding& binding() const { return m_binding; }
  /// Counts replacements of the whole binding (a mesh, a binding file, auto-bind): an edit made
  /// for an earlier binding no longer applies (RebindMarkerCommand checks it).
  [[nodiscard]] int bindingGeneration() const { return m_bindingGeneration; }
  /// Binds the marker `label` as `binding` says (nullopt: unbinds it) and returns what it was
  /// bound to before (nullopt: it was not bound), so applying the result undoes the change.
  std::optional<MarkerBinding> rebind(const std::string& label, std::optional<MarkerBinding> binding);
  /// Binds `labels` automatically (autoBind by ICP) in their first frame with all of them valid
  /// (or the options' neutral frame), head motion removed. Returns an error message or "".
  QString autoBindMarkers(const std::vector<std::string>& labels);

  /// Head-mounted reference labels; empty: the take is used as captured.
  void setStabilization(std::vector<std::string> labels);
  [[nodiscard]] const std::vector<std::string>& stabilization() const { return m_stabilization; }
  void setOptions(const FaceRigOptions& options);
  [[nodiscard]] const FaceRigOptions& options() const { return m_options; }
  /// Also draws the other method's mesh, offset beside the first along the mesh's x axis.
  void setCompare(bool on);
  [[nodiscard]] bool compare() const { return m_compare; }

  /// Why there is no rig (bad binding, labels not in the take …), or "".
  [[nodiscard]] const QString& error() const { return m_error; }
  [[nodiscard]] const FaceRig* rig() const { return m_rig.get(); }
  [[nodiscard]] const FaceRig* compareRig() const { return m_compareRig.get(); }
  /// The take the rigs see (head motion removed when stabilizing).
  [[nodiscard]] const Take& rigTake() const;
  [[nodiscard]] MeshLayer& layer() const { return *m_layer; }
  [[nodiscard]] MeshLayer& compareLayer() const { return *m_compareLayer; }
  /// The vertex of the (first) mesh under `position` (3D view widget coordinates), or −1.
  [[nodiscard]] Eigen::Index vertexAt(QPoint position) const;
  /// Where vertex `vertex` of the (first) mesh is drawn, in 3D view widget coordinates.
  [[nodiscard]] QPointF vertexPosition(Eigen::Index vertex) const;
  /// Milliseconds the last frame's deform took (−1 when it did not run).
  [[nodiscard]] double lastDeformMs() const { return m_deformMs; }
  [[nodiscard]] double lastCompareMs() const { return m_compareMs; }

signals:
  void meshChanged();
  void bindingChanged();
  /// The rigs were set up again (or could not be: error()).
  void rigChanged();
  /// A frame was deformed; compareMilliseconds is −1 when not comparing.
  void deformed(double milliseconds, double compareMilliseconds);

private:
  void restabilize();
  void rebuild();
  void updateFrame();
  void updatePlacement();
  [[nodiscard]] std::optional<Eigen::Affine3d> meshToScene(Eigen::Index frame) const;

  TakeDocument& m_document;
  MarkerView3d& m_view;
  std::unique_ptr<MeshLayer> m_layer;
  std::unique_ptr<MeshLayer> m_compareLayer;
  Mesh m_mesh;
  MeshBinding m_binding;
  int m_bindingGeneration = 0;
  std::vector<std::string> m_stabilization;
  FaceRigOptions m_options;
  bool m_compare = false;
  std::optional<Take> m_stabilized;  // the take without head motion, when stabilizing
  QString m_stabilizationError;
  std::optional<HeadMotion> m_headMotion;
  std::vector<Eigen::Index> m_viewReference;  // the view's reference markers m_viewMotion is for
  std::optional<HeadMotion> m_viewMotion;
  std::unique_ptr<FaceRig> m_rig;
  std::unique_ptr<FaceRig> m_compareRig;
  QString m_error;
  double m_deformMs = -1.0;
  double m_compareMs = -1.0;
  MeshVertices m_deformed;
};

} // namespace mocap::ui
