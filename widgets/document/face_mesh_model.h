#pragma once

#include "mocap/cleaning/head_stabilization.h"
#include "mocap/deform/face_rig.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/model/mesh.h"

#include <QObject>
#include <QString>

#include <Eigen/Geometry>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mocap::ui {

class TakeDocument;

/// The face mesh the open take drives, beside the document it follows: the mesh, its marker
/// binding, the rig settings, a FaceRig set up for the take (and, when comparing, a second rig with
/// the other method), and, when reference labels are given, a copy of the take with head motion
/// removed (the frame bindings are made in) with the head poses that put the mesh back on the head.
/// The rigs are set up again whenever the take, its samples or its markers change. Views draw it
/// (FaceMeshScene); edits of the binding go through the document's undo stack
/// (RebindMarkerCommand). Rig set-up is synchronous (a few milliseconds for a face of hundreds of
/// vertices); deform() costs O(#vertices · #controls).
class FaceMeshModel final : public QObject
{
  Q_OBJECT

public:
  explicit FaceMeshModel(TakeDocument& document, QObject* parent = nullptr);
  ~FaceMeshModel() override;

  [[nodiscard]] TakeDocument& document() const { return m_document; }

  /// Replaces the mesh (read from `path`, e.g. an OBJ or a glTF rig's neutral); a binding made
  /// for another vertex count is dropped.
  void setMesh(Mesh mesh, const QString& path = {});
  [[nodiscard]] const Mesh& mesh() const { return m_mesh; }
  [[nodiscard]] bool hasMesh() const { return m_mesh.vertexCount() > 0; }
  /// The file the mesh came from, absolute ("" when none is loaded or it was made in code).
  [[nodiscard]] const QString& meshPath() const { return m_meshPath; }
  /// Drops the mesh, binding and rigs (a new take starts without them); the options stay.
  void clear();
  void setBinding(MeshBinding binding);
  [[nodiscard]] const MeshBinding& binding() const { return m_binding; }

  /// Binds the markers of `rig` (a binding kept from another take: the actor's) that this take
  /// has; the others are remembered, not bound, and the alignment (made in the other take) is
  /// dropped, so the mesh is placed only by a rig set up on this take. O(#bound · #markers).
  void bindKeptRig(MeshBinding rig);
  /// How many markers the kept rig binds (0 when the binding was made for this take, not kept).
  [[nodiscard]] std::size_t keptRigMarkers() const { return m_keptRig.markers.size(); }
  /// What is bound in this take: "31 marker(s) bound", or with a kept rig "5 of 31 rig
  /// marker(s) found in this take".
  [[nodiscard]] QString bindingSummary() const;
  /// The binding to keep for the next take: this one, plus the kept rig's markers it does not
  /// bind (so a take without some markers does not lose them for the next). O(#bound²).
  [[nodiscard]] MeshBinding bindingToKeep() const;
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
  /// Also sets up the other method's rig, to be drawn beside the first.
  void setCompare(bool on);
  [[nodiscard]] bool compare() const { return m_compare; }

  /// Why there is no rig (bad binding, labels not in the take …), or "".
  [[nodiscard]] const QString& error() const { return m_error; }
  [[nodiscard]] const FaceRig* rig() const { return m_rig.get(); }
  [[nodiscard]] const FaceRig* compareRig() const { return m_compareRig.get(); }
  /// The take the rigs see (head motion removed when stabilizing).
  [[nodiscard]] const Take& rigTake() const;
  /// The mesh deformed to a frame by a rig of its own over a copy of rigTake(), for a job on a
  /// worker thread (this model's rig follows every edit and option change). Building it costs a
  /// FaceRig and a take copy; throws as FaceRig does for a binding that cannot rig.
  [[nodiscard]] std::function<void(Eigen::Index frame, MeshVertices& vertices)> detachedDeformer() const;

  /// The mesh deformed to `frame` by the rig (or, with `compared`, the compare rig). False when
  /// there is no such rig or the take changed under it; then the rigs are dropped, error() says
  /// why and rigChanged() is emitted.
  bool deform(Eigen::Index frame, MeshVertices& vertices, bool compared = false);
  /// Where the mesh sits in the lab at `frame`: the binding's alignment inverted, put back on the
  /// captured head when stabilizing; nullopt with neither a rig nor an aligned binding. O(1).
  [[nodiscard]] std::optional<Eigen::Affine3d> meshToLab(Eigen::Index frame) const;

signals:
  void meshChanged();
  void bindingChanged();
  /// The rigs were set up again (or could not be: error()).
  void rigChanged();

private:
  void restabilize();
  void rebuild();

  TakeDocument& m_document;
  Mesh m_mesh;
  QString m_meshPath;
  MeshBinding m_binding;
  MeshBinding m_keptRig;  // the whole binding kept from another take (bindKeptRig), else empty
  int m_bindingGeneration = 0;
  std::vector<std::string> m_stabilization;
  FaceRigOptions m_options;
  bool m_compare = false;
  std::optional<Take> m_stabilized;  // the take without head motion, when stabilizing
  QString m_stabilizationError;
  std::shared_ptr<const HeadMotion> m_headMotion;  // shared with the document's cache
  std::unique_ptr<FaceRig> m_rig;
  std::unique_ptr<FaceRig> m_compareRig;
  QString m_error;
};

} // namespace mocap::ui
