#pragma once

#include <QMainWindow>
#include <QStringList>
#include <QVariantMap>

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

class QAction;
class QDockWidget;
class QMenu;
class QTableView;
class QTimer;

namespace mocap::ui {
class Autosave;
class CleaningPresetActions;
class MarkerTablePanel;
class ReadWarningsButton;
class TakeFileActions;
class ReferenceMarkerActions;
class HeadStabilizedViewAction;
class LabellingActions;
class MarkerEditActions;
class CleaningPanel;
class BlendshapeSolvePanel;
class ReferenceVideoPanel;
class FaceMeshPanel;
class WeightCurveView;
class GapListPanel;
class HeadMarkersProposalBar;
class CurveView;
class LayoutPlanningPanel;
class ManualWindow;
class MarkerView3d;
struct ReviewSource;
class SessionScene;
class StudioSession;
class TakeDocument;
class TimelineWidget;
} // namespace mocap::ui

namespace mocap::studio {

/// The studio's main window: wires the session (its document and models) to the 3D view
/// (centre), the marker table and curves (docks), the panels and the timeline, plus menus,
/// shortcuts, recent files and remembered layout. It only wires; every view, model and command
/// lives in mocap::widgets.
class MainWindow final : public QMainWindow
{
  Q_OBJECT

public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  /// Opens `path`; on failure shows the error (unless `quiet`) and keeps the open take.
  /// Returns the error message, empty on success.
  QString openFile(const QString& path, bool quiet = false);
  [[nodiscard]] ui::TakeDocument& document() { return *m_document; }
  /// The open take's session: the document and the models the docks observe.
  [[nodiscard]] ui::StudioSession& session() { return *m_session; }
  [[nodiscard]] ui::MarkerView3d* markerView() const { return m_view3d; }
  /// The session's face mesh and posed rig as the 3D view draws them.
  [[nodiscard]] ui::SessionScene& sessionScene() const { return *m_sessionScene; }
  [[nodiscard]] QTableView* markerTable() const;
  [[nodiscard]] ui::CurveView* curveView() const { return m_curves; }
  [[nodiscard]] ui::TimelineWidget* timeline() const { return m_timeline; }
  [[nodiscard]] ui::CleaningPanel* cleaningPanel() const { return m_cleaning; }
  [[nodiscard]] ui::LayoutPlanningPanel* layoutPlanningPanel() const { return m_layoutPlanning; }
  [[nodiscard]] ui::FaceMeshPanel* faceMeshPanel() const { return m_faceMesh; }
  [[nodiscard]] ui::BlendshapeSolvePanel* blendshapeSolvePanel() const { return m_blendshapeSolve; }
  [[nodiscard]] ui::WeightCurveView* weightView() const { return m_weights; }
  [[nodiscard]] ui::ReferenceVideoPanel* referenceVideoPanel() const { return m_referenceVideo; }
  [[nodiscard]] ui::GapListPanel* gapListPanel() const { return m_gapList; }
  /// Shows and raises the dock with this object name or title (any case); false when none has it.
  bool showDock(const QString& name);
  /// Help ▸ Manual (F1): opens (or raises) the bundled manual.
  ui::ManualWindow* showManual();
  /// Loads a face mesh (and its binding when given) into the Face Mesh dock and shows it.
  /// Returns the error message, empty on success.
  QString loadFaceMesh(const QString& meshPath, const QString& bindingPath = {});
  /// Loads a blendshape rig (a .glb/.gltf, or a neutral .obj/.ply with `shapeFolder`) into the
  /// Blendshape Solve dock and shows it, then the binding (made on the rig's neutral) when given;
  /// with `solve`, then solves the take with the dock's settings. Waits for each (the command
  /// line's --rig, --solve). Returns the error, or "".
  QString loadRig(const QString& rigPath, const QString& shapeFolder = {}, const QString& bindingPath = {},
                  bool solve = false);
  /// Opens `path` in the Reference Video dock (with `offset` seconds, else the offset the take
  /// remembers for it, else 0) and shows the dock. Returns the error message, empty on success.
  QString openReferenceVideo(const QString& path, std::optional<double> offset = std::nullopt);
  /// What a review video draws: the 3D view, the face mesh scene and the posed rig as shown now.
  [[nodiscard]] ui::ReviewSource reviewSource() const;
  /// File ▸ Export Review Video…: asks for the file, size and frames, then renders with progress
  /// and Cancel (a cancelled or failed export leaves no file).
  void exportReviewVideo();
  /// Selects markers by label; unknown labels are ignored. Returns how many were found.
  int selectLabels(const QStringList& labels);
  /// Offers the takes that crashed sessions left unsaved (the newest first); returns whether
  /// one was recovered. Without `ask`, the newest is recovered without a question (--recover).
  bool offerRecovery(bool ask = true);
  [[nodiscard]] ui::Autosave* autosave() const { return m_autosave; }
  /// The Marker menu's edits of the take's head reference markers (the one editor, undoable).
  [[nodiscard]] ui::ReferenceMarkerActions* referenceMarkerActions() const { return m_referenceMarkers; }
  /// The Label menu's Track and Label and swap search (on workers, undoable).
  [[nodiscard]] ui::LabellingActions* labellingActions() const { return m_labelling; }
  /// File ▸ Save and Load Cleaning Preset on the Cleaning dock's settings.
  [[nodiscard]] ui::CleaningPresetActions* cleaningPresets() const { return m_cleaningPresets; }
  /// The bar asking to accept the head markers proposed for a take without any.
  [[nodiscard]] ui::HeadMarkersProposalBar* headMarkersBar() const { return m_headMarkersBar; }

protected:
  void closeEvent(QCloseEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void showEvent(QShowEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

private:
  void createActions();
  void createDocks();
  /// The 3D view with the head markers bar above it.
  [[nodiscard]] QWidget* centralArea();
  void updateTitle();
  void readSettings();
  void writeSettings() const;

  ui::StudioSession* m_session = nullptr;
  ui::TakeDocument* m_document = nullptr;  // the session's
  ui::Autosave* m_autosave = nullptr;
  ui::MarkerView3d* m_view3d = nullptr;
  ui::SessionScene* m_sessionScene = nullptr;  // draws into m_view3d's renderer
  ui::HeadMarkersProposalBar* m_headMarkersBar = nullptr;
  ui::MarkerEditActions* m_markerEdits = nullptr;
  ui::LabellingActions* m_labelling = nullptr;
  ui::ReferenceMarkerActions* m_referenceMarkers = nullptr;
  ui::CleaningPresetActions* m_cleaningPresets = nullptr;
  ui::TakeFileActions* m_files = nullptr;
  ui::CurveView* m_curves = nullptr;
  ui::TimelineWidget* m_timeline = nullptr;
  ui::CleaningPanel* m_cleaning = nullptr;
  ui::LayoutPlanningPanel* m_layoutPlanning = nullptr;
  ui::FaceMeshPanel* m_faceMesh = nullptr;
  ui::BlendshapeSolvePanel* m_blendshapeSolve = nullptr;
  ui::WeightCurveView* m_weights = nullptr;
  ui::ReferenceVideoPanel* m_referenceVideo = nullptr;
  QDockWidget* m_blendshapeDock = nullptr;
  QDockWidget* m_weightsDock = nullptr;
  ui::GapListPanel* m_gapList = nullptr;
  ui::ManualWindow* m_manual = nullptr;  // created on first use
  QDockWidget* m_faceMeshDock = nullptr;
  ui::MarkerTablePanel* m_table = nullptr;
  QMenu* m_viewMenu = nullptr;
  ui::HeadStabilizedViewAction* m_headStabilizedView = nullptr;
  ui::ReadWarningsButton* m_warningsButton = nullptr;
  QTimer* m_layoutSaver = nullptr;
  bool m_firstRun = false;  // saves the window layout shortly after every change
};

} // namespace mocap::studio
