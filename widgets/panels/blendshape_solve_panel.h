#pragma once

#include "dialogs/rig_export_dialog.h"

#include "mocap/deform/blendshape_solver.h"
#include "mocap/model/blendshape_rig.h"

#include <QString>
#include <QWidget>

#include <memory>
#include <optional>
#include <string>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace mocap::ui {

class ActorActions;
class BlendshapeSolveModel;
class FaceMeshModel;
class JobRunner;
class RetargetSection;
class StudioSession;
class TakeDocument;
class WeightEditActions;

/// A rig read on a worker, or why it could not be.
struct RigLoad
{
  std::shared_ptr<const BlendshapeRig> rig;
  QString path;
  QString shapeFolder;
  QString error;
};

/// A solve run on a worker, or why it failed ("" and no weights when cancelled).
struct SolveRun
{
  BlendshapeSolveResult result;
  BlendshapeSolveOptions options;
  std::size_t markers = 0;
  double setupSeconds = 0.0;
  QString error;
};

/// The Blendshape solve dock: load a rig (a glTF/GLB with morph targets, or a neutral OBJ and a
/// folder of shape OBJs; read on a worker) into the session's BlendshapeSolveModel; its neutral
/// becomes the session's face mesh (FaceMeshModel), so the binding is made and edited in the
/// Face Mesh dock; choose the method (bvls, ridge, temporal) and its λ,
/// smoothness and sparsity; Solve runs BlendshapeSolver on a worker with progress and Cancel, on
/// the take the face mesh sees (head motion removed). Then: the rig posed by the weights in the
/// 3D view (BlendshapeScene, made by whoever composes the view; its shown/beside switches here set
/// the session's ViewState, which it follows), the shapes with their peak weights (selecting them shows their
/// curves in the Weights view), the marker residual and held frames in the status, undoable
/// edits of the selected shapes over the selected frame range (scale, zero, smooth), a Live Link
/// Face recording opened as the rig's curves (undoable), and Export Rig (RigExportDialog: the
/// animated rig as FBX or GLB, the weights as CSV, plain or Live Link Face, with a retarget map
/// and key reduction as the command line has them). Settings are remembered (typed session options,
/// "blendshapeSolve/…"). Below them the Retarget section (RetargetSection) shows the curves
/// through a retarget map whose gains are edited in place.
class BlendshapeSolvePanel final : public QWidget
{
  Q_OBJECT

public:
  explicit BlendshapeSolvePanel(StudioSession& session, QWidget* parent = nullptr);
  ~BlendshapeSolvePanel() override;

  [[nodiscard]] BlendshapeSolveModel& model() const { return m_model; }
  [[nodiscard]] WeightEditActions& edits() const { return *m_edits; }
  [[nodiscard]] RetargetSection* retargetSection() const { return m_retarget; }
  /// The Actor menu's actions; the solve uses the actor they load.
  [[nodiscard]] ActorActions& actors() const { return *m_actors; }

  /// Starts reading a rig: `path` a .glb/.gltf (no folder) or a neutral .obj/.ply with
  /// `shapeFolder`. rigLoaded() tells the outcome. Returns "" or why nothing was started.
  QString loadRig(const QString& path, const QString& shapeFolder = {});
  /// Starts a solve of the take with the panel's settings; solveFinished() tells the outcome.
  /// Returns "" or why nothing was started (no rig, no binding, a job running).
  QString solve();
  void cancel();
  [[nodiscard]] bool busy() const;
  /// Blocks until the running load or solve has ended and delivers it at once, without serving
  /// the event loop (the command line's --rig, before anything is painted).
  void finishJob();
  /// The panel's background job, a load or a solve (its finished() is what a test waits on).
  [[nodiscard]] const JobRunner& jobs() const { return *m_jobs; }

  [[nodiscard]] BlendshapeSolveOptions optionsFromUi() const;
  /// Each returns "" or the error shown. exportCsv writes Frame,Time,<shape>,…, or with `liveLink`
  /// Live Link Face's own layout (live_link_face_csv.h, through liveLinkFaceMapForRig); both
  /// write as Export Rig does with no map and every frame keyed.
  QString exportCsv(const QString& path, bool liveLink);
  QString exportGlb(const QString& path);
  /// What Export Rig writes: the rig and its curves, timed as the take is, or as the recording
  /// was when the curves were read from one.
  [[nodiscard]] RigExportSource exportSource() const;
  /// Opens Export Rig with `format` chosen (the dock's Export buttons).
  void openExportDialog(RigExportFormat format);
  /// Opens a Live Link Face recording as the rig's curves (openLiveLinkRecording). Returns "" or
  /// the error shown.
  QString openLiveLinkRecording(const QString& path, const std::optional<std::string>& map = std::nullopt);

  [[nodiscard]] QString statusText() const;
  [[nodiscard]] QListWidget* shapeList() const { return m_shapes; }

signals:
  void rigLoaded(const QString& error);
  void solveFinished(const QString& error);
  /// What an edit did or why it did nothing, for the status bar.
  void message(const QString& text, int timeoutMs);

private:
  void buildUi();
  QWidget* buildRigBox();
  QWidget* buildSolveBox();
  QWidget* buildShapesBox();
  QWidget* buildDisplayBox();
  void readSettings();
  void writeSettings() const;
  void onRigLoaded(const RigLoad& load);
  /// The rig line, shape list and status for the model's rig (loaded, kept for a new take, dropped).
  void showRig();
  /// A new take: what of the rig was kept, or back to the first step.
  void onTakeContextReset(bool rigKept);
  void onSolved(SolveRun run);
  void fillShapeList();
  void applyShapeFilter();
  void onListSelectionChanged();
  void onModelSelectionChanged();
  void updateMethodFields();
  void showStatus(const QString& text, bool error = false);
  void showEditResult(const QString& why);
  void loadGltfDialog();
  void loadObjDialog();
  void openLiveLinkDialog();
  /// Writes the curves as Export Rig would with `options` (no map, every frame keyed for the dock's own exports).
  QString writeCurves(const QString& path, const WeightOutput& options);

  StudioSession& m_session;
  TakeDocument& m_document;
  FaceMeshModel& m_faceMesh;
  BlendshapeSolveModel& m_model;
  WeightEditActions* m_edits = nullptr;
  ActorActions* m_actors = nullptr;
  JobRunner* m_jobs = nullptr;  // one job at a time: a rig load or a solve
  bool m_loadingSettings = false;
  bool m_syncingSelection = false;

  QLabel* m_rigLabel = nullptr;
  QComboBox* m_method = nullptr;
  QCheckBox* m_autoLambda = nullptr;
  QDoubleSpinBox* m_lambda = nullptr;
  QDoubleSpinBox* m_smoothness = nullptr;
  QDoubleSpinBox* m_sparsity = nullptr;
  QPushButton* m_solve = nullptr;
  QLabel* m_status = nullptr;
  QLineEdit* m_filter = nullptr;
  QListWidget* m_shapes = nullptr;
  QDoubleSpinBox* m_scaleFactor = nullptr;
  QDoubleSpinBox* m_cutoff = nullptr;
  QCheckBox* m_show = nullptr;
  QCheckBox* m_beside = nullptr;
  QPushButton* m_exportCsv = nullptr;
  QPushButton* m_exportGlb = nullptr;
  QPushButton* m_openLiveLink = nullptr;
  RetargetSection* m_retarget = nullptr;
};

} // namespace mocap::ui
