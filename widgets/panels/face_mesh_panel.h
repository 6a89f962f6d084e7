#pragma once

#include "mocap/deform/face_rig.h"

#include <QPoint>
#include <QString>
#include <QWidget>

#include <string>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;
class QSpinBox;
class QStackedWidget;
class QToolButton;
class QUndoStack;

namespace mocap::ui {

class FaceMeshModel;
class FaceMeshScene;
class MarkerView3d;
class ReferenceMarkersRow;
class StudioSession;
class TakeDocument;
class ViewState;

/// The Face mesh dock: load a mesh (OBJ/PLY) and a marker binding (JSON), bind automatically or
/// edit the binding by picking (select a marker, then click the mesh vertex it belongs to; each
/// edit undoable on the document's stack, and the status says the marker's new residual), choose
/// RBF (kernel, radius, regions) or Laplacian (weights, constraint weight, rotations) deformation
/// or both side by side, and read the per-frame deform time. The mesh, binding and rigs live in
/// the session's FaceMeshModel (document/), drawn by a FaceMeshScene (views/) that whoever composes
/// the 3D view makes; the panel only observes it (its deform time, the vertex under a click). The
/// binding line says what is bound in this take, and how many of a kept rig's markers it has.
/// Settings are remembered (typed session options, "faceMesh/…").
class FaceMeshPanel final : public QWidget
{
  Q_OBJECT

public:
  /// `scene` draws the session's face mesh in `view`.
  FaceMeshPanel(StudioSession& session, MarkerView3d& view, const FaceMeshScene& scene, QWidget* parent = nullptr);
  ~FaceMeshPanel() override;
  /// How far `marker` (bound) sits from its mesh point once the rig places the neutral frame on
  /// the mesh, in take units; NaN without a rig or with the marker missing there. O(1).
  [[nodiscard]] double pickResidual(Eigen::Index marker) const;
  /// The panel's status line (the last pick: vertex and residual, or what to do next).
  [[nodiscard]] QString statusText() const;

  /// The mesh, binding and rigs the take drives (the session's).
  [[nodiscard]] FaceMeshModel& model() const { return m_model; }
  /// Their drawing in the 3D view (observed, not owned).
  [[nodiscard]] const FaceMeshScene& scene() const { return m_scene; }
  [[nodiscard]] QUndoStack* undoStack() const { return m_undo; }

  /// Each returns an error message (also shown in the panel) or "".
  QString loadMesh(const QString& path);
  QString loadBinding(const QString& path);
  /// What the binding line says, e.g. "31 marker(s) bound" or "5 of 31 rig markers found in this take".
  [[nodiscard]] QString bindingSummary() const;
  QString saveBinding(const QString& path);
  /// Binds the selected markers (three or more) or else every labelled marker that is not one of
  /// the take's reference markers and is present in the most complete frame.
  QString autoBind();

  /// Picking mode: with one marker selected, a click on the mesh binds it to the vertex under the
  /// cursor (a click on another marker selects that one instead).
  void setPicking(bool on);
  [[nodiscard]] bool picking() const;
  /// The marker a vertex click binds (the one selected alone), or "".
  [[nodiscard]] const std::string& pendingLabel() const { return m_pendingLabel; }
  /// The per-frame deform time shown, e.g. "RBF 0.012 ms".
  [[nodiscard]] QString timingText() const;

signals:
  /// The user asked to edit the reference markers (the main window opens the one editor).
  void editReferenceMarkersRequested();

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  /// Binds the pending marker to the vertex under `position`; false when nothing was bound.
  bool pickVertex(QPoint position);
  void buildUi();
  void readSettings();
  void writeSettings() const;
  void applyOptions();
  [[nodiscard]] FaceRigOptions optionsFromUi() const;
  void onTakeReset();
  void onSelectionChanged();
  void updateBindingSummary();
  void updateMeshLabel();
  void updateRigStatus();
  void showError(const QString& message);
  void loadMeshDialog();
  void loadBindingDialog();
  void saveBindingDialog();

  TakeDocument& m_document;
  MarkerView3d& m_view;
  FaceMeshModel& m_model;
  const FaceMeshScene& m_scene;
  ViewState& m_viewState;  // the session's: the mesh look is set there, the scene follows it
  QUndoStack* m_undo = nullptr;  // the document's: binding edits undo in order with every other edit
  std::string m_pendingLabel;
  QPoint m_pressPosition;
  bool m_loadingSettings = false;

  QLabel* m_meshLabel = nullptr;
  QLabel* m_bindingLabel = nullptr;
  QToolButton* m_pick = nullptr;
  ReferenceMarkersRow* m_reference = nullptr;
  QSpinBox* m_neutral = nullptr;
  QComboBox* m_method = nullptr;
  QStackedWidget* m_methodPages = nullptr;
  QComboBox* m_kernel = nullptr;
  QDoubleSpinBox* m_radius = nullptr;
  QCheckBox* m_regions = nullptr;
  QComboBox* m_weights = nullptr;
  QDoubleSpinBox* m_constraintWeight = nullptr;
  QSpinBox* m_rotations = nullptr;
  QCheckBox* m_compare = nullptr;
  QCheckBox* m_edges = nullptr;
  QSlider* m_opacity = nullptr;
  QLabel* m_timing = nullptr;
  QLabel* m_status = nullptr;
};

} // namespace mocap::ui
