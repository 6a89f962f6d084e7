#include "main_window.h"

#include "language.h"

#include "actions/labelling_actions.h"
#include "actions/head_stabilized_view_action.h"
#include "actions/marker_edit_actions.h"

#include "commands/record_step_command.h"
#include "commands/set_reference_markers_command.h"
#include "actions/actor_actions.h"
#include "dialogs/export_dialog.h"
#include "dialogs/reference_markers_dialog.h"
#include "dialogs/job_dialog.h"
#include "dialogs/manual_window.h"
#include "dialogs/preferences_dialog.h"
#include "dialogs/read_warnings_dialog.h"
#include "dialogs/review_export_dialog.h"
#include "document/autosave.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "models/marker_table_model.h"
#include "panels/cleaning_panel.h"
#include "document/blendshape_solve_model.h"
#include "panels/blendshape_solve_panel.h"
#include "panels/face_mesh_panel.h"
#include "panels/gap_fill_step.h"
#include "panels/gap_list_panel.h"
#include "panels/head_markers_proposal_bar.h"
#include "panels/head_stabilization_step.h"
#include "panels/history_panel.h"
#include "panels/layout_planning_panel.h"
#include "panels/reference_video_panel.h"
#include "document/layout_plan_model.h"
#include "document/reference_video.h"
#include "document/reference_videos.h"
#include "panels/smoothing_step.h"
#include "panels/spike_step.h"
#include "views/curve_view.h"
#include "views/weight_curve_view.h"
#include "document/face_mesh_model.h"
#include "views/marker_view_3d.h"
#include "views/model_outputs_note.h"
#include "views/status_timeout.h"
#include "views/steady_label.h"
#include "views/blendshape_scene.h"
#include "views/face_mesh_scene.h"
#include "views/mesh_layer.h"
#include "views/review_scene.h"
#include "views/sample_colors.h"
#include "views/timeline_widget.h"
#include "views/wheel_guard.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCheckBox>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHeaderView>
#include <QLocale>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressDialog>
#include <QScreen>
#include <QScrollArea>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <QSettings>
#include <QSortFilterProxyModel>
#include <QStatusBar>
#include <QTabBar>
#include <QTableView>
#include <QToolBar>
#include <QUndoStack>
#include <QUndoView>

#include <algorithm>
#include <memory>
#include <utility>

#include "mocap/cleaning/head_stabilization.h"
#include "mocap/base/length_unit.h"
#include "mocap/model/marker_set.h"
#include "mocap/io/take_io.h"
#include "mocap/base/file_io.h"
#include "mocap/batch/clean_preset.h"

namespace mocap::studio {

namespace {
constexpr int kMaxRecent = 8;
const char* const kOpenFilter =
    QT_TRANSLATE_NOOP("mocap::studio::MainWindow", "Motion capture (*.c3d *.trc);;All files (*)");

/// "a, b, c" for a message.
QString joinLabels(const std::vector<std::string>& labels)
{
  QStringList list;
  for (const std::string& label : labels)
    list << QString::fromStdString(label);
  return list.join(QStringLiteral(", "));
}
} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_session(new ui::StudioSession(this)), m_document(&m_session->document())
{
  setAcceptDrops(true);
  ui::WheelGuard::install();
  m_view3d = new ui::MarkerView3d(*m_document, this);
  setCentralWidget(centralArea());
  m_timeline = new ui::TimelineWidget(*m_document, this);
  auto* timelineBar = new QToolBar(tr("Timeline"), this);
  timelineBar->setObjectName(QStringLiteral("timelineBar"));
  timelineBar->addWidget(m_timeline);
  timelineBar->setMovable(false);
  addToolBar(Qt::BottomToolBarArea, timelineBar);
  m_markerEdits = new ui::MarkerEditActions(*m_document, *this, this);
  m_labelling = new ui::LabellingActions(*m_document, *this, this);
  const auto showMessage = [this](const QString& text, int timeoutMs) { statusBar()->showMessage(text, timeoutMs); };
  connect(m_markerEdits, &ui::MarkerEditActions::message, this, showMessage);
  connect(m_labelling, &ui::LabellingActions::message, this, showMessage);
  createDocks();
  createActions();
  m_status = new QLabel(this);
  m_status->setObjectName(QStringLiteral("frameStatus"));
  statusBar()->addPermanentWidget(m_status);
  m_warningsButton = new QToolButton(this);
  m_warningsButton->setObjectName(QStringLiteral("readWarningsButton"));
  m_warningsButton->setAutoRaise(true);
  m_warningsButton->hide();
  connect(m_warningsButton, &QToolButton::clicked, this, &MainWindow::openReadWarnings);
  statusBar()->addPermanentWidget(m_warningsButton);
  statusBar()->addPermanentWidget(new ui::ModelOutputsNote(*m_document, this));
  connect(m_timeline, &ui::TimelineWidget::message, this, [this](const QString& text) {
    statusBar()->showMessage(text, ui::kStatusMessageMs);
  });

  connect(m_document, &ui::TakeDocument::modifiedChanged, this, &MainWindow::updateTitle);
  connect(m_document, &ui::TakeDocument::filePathChanged, this, &MainWindow::updateTitle);
  connect(m_document, &ui::TakeDocument::selectionChanged, this, &MainWindow::syncTableSelection);
  // The status line follows both the frame and the selection it names.
  auto updateStatusLine = [this] {
    const Take& take = m_document->take();
    const auto text = [&](Eigen::Index frame, std::size_t selected) {
      // The take's range in the file's numbering: a take starting at frame 63 is not "555 of 493".
      return tr("Frame %1 of %2–%3 — %4 markers selected")
          .arg(static_cast<qlonglong>(take.firstFrame() + frame))
          .arg(static_cast<qlonglong>(take.firstFrame()))
          .arg(static_cast<qlonglong>(take.firstFrame() + std::max<Eigen::Index>(take.frameCount() - 1, 0)))
          .arg(static_cast<qulonglong>(selected));
    };
    const std::pair<Eigen::Index, Eigen::Index> fitted{take.frameCount(), take.markerCount()};
    if (fitted != m_statusFitsTake) {  // sized for the take's widest line
      ui::fixLabelSizeFor(*m_status, text(take.frameCount() - 1, static_cast<std::size_t>(take.markerCount())));
      m_statusFitsTake = fitted;
    }
    m_status->setText(text(m_document->currentFrame(), m_document->selection().size()));
  };
  connect(m_document, &ui::TakeDocument::currentFrameChanged, this, updateStatusLine);
  connect(m_document, &ui::TakeDocument::selectionChanged, this, updateStatusLine);
  m_autosave = new ui::Autosave(*m_document, {}, this);
  connect(m_autosave, &ui::Autosave::failed, this, [this](const QString& message) {
    statusBar()->showMessage(tr("Autosave failed: %1").arg(message), 2 * ui::kStatusMessageMs);
  });
  m_autosave->setSessionProvider([this] { return recoverySession(); });
  readSettings();
  updateTitle();
}

MainWindow::~MainWindow() = default;

void MainWindow::createDocks()
{
  m_tableModel = new ui::MarkerTableModel(*m_document, this);
  m_proxy = new QSortFilterProxyModel(this);
  m_proxy->setSourceModel(m_tableModel);
  m_proxy->setSortRole(Qt::UserRole);
  m_table = new QTableView(this);
  m_table->setModel(m_proxy);
  m_table->setSortingEnabled(true);
  m_table->sortByColumn(-1, Qt::AscendingOrder);  // file order until the user sorts
  m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
  m_table->verticalHeader()->hide();
  m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  m_table->horizontalHeader()->setStretchLastSection(true);
  connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
    if (m_syncingSelection)
      return;
    std::vector<Eigen::Index> markers;
    for (const QModelIndex& row : m_table->selectionModel()->selectedRows())
      markers.push_back(m_proxy->mapToSource(row).row());
    m_document->setSelection(std::move(markers));
  });
  addDock(tr("Markers"), QStringLiteral("markersDock"), m_table, Qt::LeftDockWidgetArea, DockContent::Fixed);

  m_curves = new ui::CurveView(*m_document, this);
  QDockWidget* curveDock =
      addDock(tr("Curves"), QStringLiteral("curvesDock"), m_curves, Qt::BottomDockWidgetArea, DockContent::Fixed);

  m_cleaning = new ui::CleaningPanel(*m_document, this);
  m_cleaning->addStep(new ui::SpikeStep(*m_document, m_cleaning));
  auto* gapFillStep = new ui::GapFillStep(*m_document, m_cleaning);
  m_cleaning->addStep(gapFillStep);
  m_cleaning->addStep(new ui::SmoothingStep(m_cleaning));
  // Last: its preview moves every marker, not something to compute on every open.
  m_cleaning->addStep(new ui::HeadStabilizationStep(*m_document, m_cleaning));
  QDockWidget* historyDock = addDock(tr("History"), QStringLiteral("historyDock"),
                                     new ui::HistoryPanel(*m_document, this), Qt::RightDockWidgetArea);
  historyDock->hide();  // View ▸ History shows it (clicking an entry undoes or redoes to it)

  QDockWidget* cleaningDock = addDock(tr("Cleaning"), QStringLiteral("cleaningDock"), m_cleaning, Qt::RightDockWidgetArea);

  // Marker layout planning (issue 7): its selected layout is highlighted in the 3D view.
  m_layoutPlanning = new ui::LayoutPlanningPanel(*m_session, this);
  QDockWidget* layoutDock =
      addDock(tr("Layout planning"), QStringLiteral("layoutPlanningDock"), m_layoutPlanning, Qt::RightDockWidgetArea,
              DockContent::Fixed);  // scrolls its form itself, under a fixed Run row
  tabifyDockWidget(cleaningDock, layoutDock);
  m_gapList = new ui::GapListPanel(*m_document, this);  // issue 13: every gap, filled one by one or checked
  QDockWidget* gapDock = addDock(tr("Gaps"), QStringLiteral("gapListDock"), m_gapList, Qt::RightDockWidgetArea);
  tabifyDockWidget(cleaningDock, gapDock);
  connect(m_gapList, &ui::GapListPanel::frameRangeRequested, m_curves, &ui::CurveView::setVisibleRange);
  // One set of fill rules: the Gaps dock fills past the Cleaning panel's only when told to.
  m_gapList->setFillRules(gapFillStep->currentOptions());
  connect(gapFillStep, &ui::CleaningStep::changed, m_gapList,
          [this, gapFillStep] { m_gapList->setFillRules(gapFillStep->currentOptions()); });
  cleaningDock->raise();
  // The highlight shows only while the dock is on screen: leaving the panel (another tab raised,
  // the dock closed) gives the 3D view its sample-state colours back, returning shows it again.
  auto showLayout = [this, layoutDock] {
    ui::LayoutHighlight shown = layoutDock->isVisible() ? m_session->layoutPlan().highlight() : ui::LayoutHighlight{};
    m_view3d->setLayoutHighlight(std::move(shown.kept), std::move(shown.reference));
  };
  connect(&m_session->layoutPlan(), &ui::LayoutPlanModel::changed, this, showLayout);
  connect(&m_session->layoutPlan(), &ui::LayoutPlanModel::highlightChanged, this, showLayout);
  connect(layoutDock, &QDockWidget::visibilityChanged, this, showLayout);
  // Every panel shows the take's reference markers and sends the user to the one editor.
  connect(m_layoutPlanning, &ui::LayoutPlanningPanel::editReferenceMarkersRequested, this,
          &MainWindow::editReferenceMarkers);
  connect(m_cleaning->step<ui::HeadStabilizationStep>(), &ui::HeadStabilizationStep::editReferenceMarkersRequested,
          this, &MainWindow::editReferenceMarkers);
  m_faceMesh = new ui::FaceMeshPanel(*m_session, *m_view3d, this);
  connect(m_faceMesh, &ui::FaceMeshPanel::editReferenceMarkersRequested, this, &MainWindow::editReferenceMarkers);
  m_faceMeshDock = addDock(tr("Face Mesh"), QStringLiteral("faceMeshDock"), m_faceMesh, Qt::RightDockWidgetArea);
  tabifyDockWidget(cleaningDock, m_faceMeshDock);
  m_faceMeshDock->hide();  // View ▸ Face Mesh shows it

  m_blendshapeSolve = new ui::BlendshapeSolvePanel(*m_session, *m_view3d, this);
  connect(m_blendshapeSolve, &ui::BlendshapeSolvePanel::message, statusBar(), &QStatusBar::showMessage);
  m_blendshapeDock =
      addDock(tr("Blendshape Solve"), QStringLiteral("blendshapeSolveDock"), m_blendshapeSolve, Qt::RightDockWidgetArea);
  tabifyDockWidget(cleaningDock, m_blendshapeDock);
  m_blendshapeDock->hide();  // View ▸ Blendshape Solve shows it

  m_referenceVideo = new ui::ReferenceVideoPanel(*m_session, this);
  QDockWidget* videoDock =
      addDock(tr("Reference Video"), QStringLiteral("referenceVideoDock"), m_referenceVideo, Qt::RightDockWidgetArea);
  tabifyDockWidget(cleaningDock, videoDock);
  videoDock->hide();  // View ▸ Reference Video shows it, and opening a take that remembers videos
  connect(&m_session->referenceVideos(), &ui::ReferenceVideos::restored, this, [this](int count) {
    if (count > 0)
      (void)showDock(QStringLiteral("referenceVideoDock"));
  });

  m_weights = new ui::WeightCurveView(*m_document, m_session->blendshapes(), this);
  m_weightsDock =
      addDock(tr("Weights"), QStringLiteral("weightsDock"), m_weights, Qt::BottomDockWidgetArea, DockContent::Fixed);
  tabifyDockWidget(curveDock, m_weightsDock);
  m_weightsDock->hide();  // shown with the first solve, or from View ▸ Weights
  connect(m_blendshapeSolve, &ui::BlendshapeSolvePanel::solveFinished, this, [this](const QString& error) {
    if (!error.isEmpty())
      return;
    // The first solve of a rig: show its curves, and frame the posed rig with the markers.
    if (!m_weightsDock->isVisible())
      m_view3d->resetCamera();
    m_weightsDock->show();
    m_weightsDock->raise();
  });
}

QString MainWindow::openReferenceVideo(const QString& path, std::optional<double> offset)
{
  const QString error = m_referenceVideo->openVideo(path);
  if (error.isEmpty() && offset)
    m_session->referenceVideos().current()->setOffset(*offset);
  (void)showDock(QStringLiteral("referenceVideoDock"));
  return error;
}

QString MainWindow::loadRig(const QString& rigPath, const QString& shapeFolder, const QString& bindingPath, bool solve)
{
  m_blendshapeDock->show();
  m_blendshapeDock->raise();
  QString error = m_blendshapeSolve->loadRig(rigPath, shapeFolder);
  m_blendshapeSolve->finishJob();
  if (error.isEmpty() && !m_session->blendshapes().hasRig())
    error = m_blendshapeSolve->statusText();
  if (error.isEmpty() && !bindingPath.isEmpty())
    error = m_faceMesh->loadBinding(bindingPath);
  if (error.isEmpty() && solve) {
    error = m_blendshapeSolve->solve();
    m_blendshapeSolve->finishJob();
    if (error.isEmpty() && !m_session->blendshapes().hasResult())
      error = m_blendshapeSolve->statusText();
  }
  return error;
}

QString MainWindow::loadFaceMesh(const QString& meshPath, const QString& bindingPath)
{
  QString error = m_faceMesh->loadMesh(meshPath);
  if (error.isEmpty() && !bindingPath.isEmpty())
    error = m_faceMesh->loadBinding(bindingPath);
  m_faceMeshDock->show();
  m_faceMeshDock->raise();
  m_view3d->resetCamera();  // frame the mesh with the markers
  return error;
}

void MainWindow::exportAnimation()
{
  ui::ExportDialog dialog(*m_document, this);
  const ui::FaceMeshModel& mesh = m_session->faceMesh();
  if (mesh.rig()) {
    try {  // the export runs on a worker thread: with a rig of its own
      dialog.setMeshSource(mesh.mesh(), mesh.detachedDeformer(), QStringLiteral("face"));
    } catch (const std::exception& e) {
      QMessageBox::warning(this, tr("Export Animation"),
                           tr("The face mesh cannot be exported: %1").arg(QString::fromStdString(e.what())));
    }
  }
  dialog.exec();
}

ui::ReviewSource MainWindow::reviewSource() const
{
  ui::ReviewSource source;
  source.session = m_session;
  source.settings = ui::viewSettings(*m_view3d);
  source.settings.meshOpacity = m_faceMesh->scene().layer().opacity();
  source.settings.meshEdges = m_faceMesh->scene().layer().edgesVisible();
  source.settings.rigShown = m_blendshapeSolve->scene().shown();
  source.settings.rigBeside = m_blendshapeSolve->scene().beside();
  return source;
}

void MainWindow::exportReviewVideo()
{
  if (!m_document->hasTake())
    return;
  const ui::ReferenceVideo* video = m_session->referenceVideos().current();
  const bool shown = video && video->isOpen();
  ui::ReviewExportDialog dialog(*m_document, shown ? video->path() : QString(), video ? video->offset() : 0.0, this);
  if (dialog.exec() != QDialog::Accepted)
    return;
  const ui::ReviewRequest request = dialog.request();
  QProgressDialog progress(tr("Rendering the review video…"), tr("Cancel"), 0,
                           static_cast<int>(request.last - request.first + 1), this);
  progress.setWindowModality(Qt::WindowModal);
  progress.setMinimumDuration(300);
  // Frames render on this thread (the view's GL context is here); events are served between them.
  const ui::ReviewOutcome outcome = ui::exportReview(reviewSource(), request, [&progress](long long done, long long) {
    progress.setValue(static_cast<int>(done));
    QCoreApplication::processEvents();
    return !progress.wasCanceled();
  });
  progress.reset();
  if (outcome.cancelled) {
    statusBar()->showMessage(tr("Review video cancelled; nothing was written."), ui::kStatusMessageMs);
    return;
  }
  if (!outcome.done) {
    QMessageBox::warning(this, tr("Export Review Video"), tr("The review video was not written: %1").arg(outcome.error));
    return;
  }
  const QString written = QString::fromStdString(outcome.encoding.path.string());
  const QString codec = QString::fromStdString(outcome.encoding.codec);
  if (outcome.encoding.path != request.output)
    QMessageBox::information(this, tr("Export Review Video"),
                             tr("This system has no MP4 encoder, so the video was written as Motion JPEG AVI: %1")
                                 .arg(written));
  statusBar()->showMessage(tr("Wrote %1 (%2 frames, %3)").arg(written).arg(outcome.frames).arg(codec), 8000);
}

QAction* MainWindow::addRememberedToggle(QMenu* menu, const QString& text, const QString& settingsKey,
                                         const std::function<void(bool)>& apply)
{
  QAction* action = menu->addAction(text);
  action->setCheckable(true);
  action->setChecked(QSettings().value(settingsKey, false).toBool());
  apply(action->isChecked());
  connect(action, &QAction::toggled, this, [apply, settingsKey](bool on) {
    apply(on);
    QSettings().setValue(settingsKey, on);
  });
  return action;
}

void MainWindow::createActions()
{
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&Open…"), QKeySequence::Open, this, &MainWindow::openDialog);
  m_recentMenu = file->addMenu(tr("Open &Recent"));
  QAction* keepRig = addRememberedToggle(file, tr("&Keep Face Rig for the Next Take"), QStringLiteral("session/keepRig"),
                                         [this](bool on) { m_session->setKeepRig(on); });
  keepRig->setObjectName(QStringLiteral("keepRigAction"));
  keepRig->setToolTip(tr("Opening another take keeps the face mesh, its marker binding and the blendshape rig (the "
                         "actor's), bound to the markers the new take has; off, every take starts without them"));
  connect(m_session, &ui::StudioSession::takeContextReset, this, [this](bool rigKept) {
    if (rigKept)
      statusBar()->showMessage(tr("Face rig kept for this take: %1").arg(m_session->faceMesh().bindingSummary()),
                               2 * ui::kStatusMessageMs);
  });
  file->addSeparator();
  file->addAction(tr("&Save"), QKeySequence::Save, this, &MainWindow::save);
  file->addAction(tr("Save &As…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S), this, &MainWindow::saveAs);
  file->addAction(tr("&Export…"), QKeySequence(Qt::CTRL | Qt::Key_E), this, &MainWindow::exportDialog);
  file->addAction(tr("Export Ani&mation…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E), this,
                  &MainWindow::exportAnimation);
  file->addAction(tr("Export Re&view Video…"), QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_E), this,
                  &MainWindow::exportReviewVideo);
  file->addAction(tr("Export Ri&g…"), this, [this] { m_blendshapeSolve->openExportDialog(ui::RigExportFormat::Fbx); })
      ->setToolTip(tr("The solved rig as FBX or glTF, or its curves as CSV, through a retarget map (Blendshape Solve)"));
  file->addAction(tr("Save &Cleaning Preset…"), this, &MainWindow::saveCleaningPresetDialog);
  file->addAction(tr("&Load Cleaning Preset…"), this, &MainWindow::loadCleaningPresetDialog)
      ->setObjectName(QStringLiteral("loadCleaningPresetAction"));
  file->addSeparator();
  file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
  redo->setShortcut(QKeySequence::Redo);
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  QAction* deleteRange = edit->addAction(tr("&Delete Range"), QKeySequence::Delete, m_markerEdits, &ui::MarkerEditActions::deleteRange);
  deleteRange->setToolTip(tr("Make the selected frame range of the selected markers a gap (Shift-drag on the curves)"));
  edit->addAction(tr("&Rename Marker…"), QKeySequence(Qt::Key_F2), this, [this] {
    const QModelIndex current = m_table->currentIndex();
    if (current.isValid())
      m_table->edit(current.siblingAtColumn(ui::MarkerTableModel::LabelColumn));
  });
  edit->addSeparator();
  QAction* preferences =
      edit->addAction(tr("&Preferences…"), QKeySequence(Qt::CTRL | Qt::Key_Comma), this, &MainWindow::editPreferences);
  preferences->setMenuRole(QAction::PreferencesRole);

  createMarkerMenu();
  createLabelMenu();
  menuBar()->addMenu(m_blendshapeSolve->actors().createMenu(this));

  m_viewMenu = menuBar()->addMenu(tr("&View"));
  m_viewMenu->addAction(tr("&Reset Camera"), QKeySequence(Qt::CTRL | Qt::Key_R), m_view3d, &ui::MarkerView3d::resetCamera);
  auto* upGroup = new QActionGroup(this);
  m_yUp = m_viewMenu->addAction(tr("Y Axis Up"));
  m_zUp = m_viewMenu->addAction(tr("Z Axis Up"));
  for (QAction* a : {m_yUp, m_zUp}) {
    a->setCheckable(true);
    upGroup->addAction(a);
  }
  connect(m_yUp, &QAction::triggered, this, [this] { changePreferences([](ui::Preferences& p) { p.upAxis = 1; }); });
  connect(m_zUp, &QAction::triggered, this, [this] { changePreferences([](ui::Preferences& p) { p.upAxis = 2; }); });
  m_trails = m_viewMenu->addAction(tr("&Trails"));
  m_trails->setCheckable(true);
  connect(m_trails, &QAction::triggered, this, [this](bool on) {
    changePreferences([on](ui::Preferences& p) { p.trailFrames = on ? std::max(p.trailFrames, 50) : 0; });
  });
  QAction* links = addRememberedToggle(m_viewMenu, tr("Marker &Links"), QStringLiteral("view/links"),
                                       [this](bool on) { m_view3d->setLinksVisible(on); });
  links->setShortcut(QKeySequence(Qt::Key_L));
  QAction* outputs = addRememberedToggle(m_viewMenu, tr("Show &Model Outputs"), QStringLiteral("view/modelOutputs"),
                                         [this](bool on) { m_document->setShowModelOutputs(on); });
  outputs->setObjectName(QStringLiteral("showModelOutputsAction"));
  outputs->setToolTip(tr("Draw and gap-list the joint angles, forces, moments and powers a C3D file stores as points "
                         "(they are never cleaned)"));
  QAction* follow = addRememberedToggle(m_viewMenu, tr("&Follow Head"), QStringLiteral("view/followHead"),
                                        [this](bool on) { m_view3d->setFollowHead(on); });
  follow->setObjectName(QStringLiteral("followHeadAction"));
  follow->setShortcut(QKeySequence(Qt::Key_F));
  follow->setToolTip(tr("Keep the camera on the head as it moves (the centroid of the head markers)"));
  QMenu* languages = m_viewMenu->addMenu(tr("&Language"));
  auto* languageGroup = new QActionGroup(this);
  const QString current = QSettings().value(QStringLiteral("language"), defaultLanguage()).toString();
  for (const QString& code : availableLanguages()) {
    QAction* action = languages->addAction(languageName(code));
    action->setCheckable(true);
    action->setChecked(code == current);
    languageGroup->addAction(action);
    connect(action, &QAction::triggered, this, [this, code] {
      changePreferences([code](ui::Preferences& p) { p.language = code; });
      QMessageBox::information(this, tr("Language"), tr("The new language is used from the next start."));
    });
  }
  m_viewMenu->addSeparator();
  for (QDockWidget* dock : findChildren<QDockWidget*>())
    m_viewMenu->addAction(dock->toggleViewAction());
  m_viewMenu->addSeparator();
  m_headStabilizedView = new ui::HeadStabilizedViewAction(*m_document, *m_view3d, *this, this);
  connect(m_headStabilizedView, &ui::HeadStabilizedViewAction::message, this,
          [this](const QString& text, int timeoutMs) { statusBar()->showMessage(text, timeoutMs); });
  m_viewMenu->addAction(m_headStabilizedView->action());

  // Transport keys work wherever the focus is (window shortcuts).
  auto addShortcut = [this](const QKeySequence& keys, auto slot) {
    auto* action = new QAction(this);
    action->setShortcut(keys);
    action->setShortcutContext(Qt::WindowShortcut);
    connect(action, &QAction::triggered, this, slot);
    addAction(action);
  };
  addShortcut(QKeySequence(Qt::Key_Space), [this] { m_timeline->togglePlaying(); });
  addShortcut(QKeySequence(Qt::Key_Right), [this] { m_timeline->step(1); });
  addShortcut(QKeySequence(Qt::Key_Left), [this] { m_timeline->step(-1); });
  addShortcut(QKeySequence(Qt::SHIFT | Qt::Key_Right), [this] { m_timeline->step(10); });
  addShortcut(QKeySequence(Qt::SHIFT | Qt::Key_Left), [this] { m_timeline->step(-10); });
  addShortcut(QKeySequence(Qt::Key_Home), [this] { m_document->setCurrentFrame(0); });
  addShortcut(QKeySequence(Qt::Key_End), [this] { m_document->setCurrentFrame(m_document->take().frameCount() - 1); });
  addShortcut(QKeySequence(Qt::Key_PageDown), [this] { m_timeline->jumpToGap(1); });
  addShortcut(QKeySequence(Qt::Key_PageUp), [this] { m_timeline->jumpToGap(-1); });
  addShortcut(QKeySequence(Qt::CTRL | Qt::Key_PageDown), [this] { m_timeline->jumpToFlag(1); });
  addShortcut(QKeySequence(Qt::CTRL | Qt::Key_PageUp), [this] { m_timeline->jumpToFlag(-1); });

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  QAction* manual = help->addAction(tr("&Manual"), this, &MainWindow::showManual);
  manual->setShortcut(QKeySequence::HelpContents);
  help->addAction(tr("&About Mocap Studio"), this, [this] {
    QMessageBox::about(this, tr("About Mocap Studio"),
                       tr("<b>Mocap Studio %1</b><p>Cleaning and using facial optical motion capture.</p>")
                               .arg(QStringLiteral(MOCAP_VERSION)) +
                           tr("<p>Keys: Space play/pause, ←/→ step (Shift: 10), Home/End, PgUp/PgDn previous/next "
                              "gap, Ctrl+PgUp/PgDn previous/next bad point, Ctrl+R reset camera, L marker links, "
                              "H hide, Shift+H show all, Ctrl+drag rubber-band selection, Ctrl+B head-stabilized "
                              "view, F camera follows the head, Ctrl+Shift+S save as.</p>"));
  });
  updateRecentMenu();
}

void MainWindow::applyPreferences(const ui::Preferences& preferences)
{
  m_view3d->setMarkerScale(preferences.markerSizePercent / 100.0);
  m_view3d->setTrailFrames(preferences.trailFrames);
  m_view3d->setUpAxis(preferences.upAxis);
  m_autosave->setInterval(preferences.autosaveMinutes * 60 * 1000);
  const LengthUnit unit = parseLengthUnit(preferences.displayUnit.toStdString()).value_or(LengthUnit::Millimetre);
  m_curves->setDisplayUnit(unit);
  if (auto* smoothing = m_cleaning->step<ui::SmoothingStep>())
    smoothing->setDisplayUnit(unit);
  if (!(preferences.colors == ui::colorScheme())) {
    ui::setColorScheme(preferences.colors);
    m_view3d->refreshColors();
    m_curves->update();
  }
  m_view3d->setDisplayUnit(unit);
  m_yUp->setChecked(preferences.upAxis == 1);
  m_zUp->setChecked(preferences.upAxis == 2);
  m_trails->setChecked(preferences.trailFrames > 0);
}

void MainWindow::changePreferences(const std::function<void(ui::Preferences&)>& change)
{
  ui::Preferences preferences = ui::Preferences::load();
  change(preferences);
  preferences = preferences.clamped();
  preferences.save();
  applyPreferences(preferences);
}

void MainWindow::editPreferences()
{
  ui::Preferences preferences = ui::Preferences::load();
  if (preferences.language.isEmpty())
    preferences.language = defaultLanguage();
  QStringList names;
  for (const QString& code : availableLanguages())
    names << languageName(code);
  ui::PreferencesDialog dialog(preferences, availableLanguages(), names, this);
  if (dialog.exec() != QDialog::Accepted)
    return;
  const ui::Preferences chosen = dialog.preferences();
  if (chosen.language != preferences.language)
    QMessageBox::information(this, tr("Language"), tr("The new language is used from the next start."));
  chosen.save();
  applyPreferences(chosen);
}

QWidget* MainWindow::centralArea()
{
  auto* area = new QWidget(this);
  auto* layout = new QVBoxLayout(area);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  m_headMarkersBar = new ui::HeadMarkersProposalBar(*m_document, area);
  connect(m_headMarkersBar, &ui::HeadMarkersProposalBar::acceptRequested, this,
          [this](const std::vector<Eigen::Index>& markers) {
            if (changeReferenceMarkers(markers))
              statusBar()->showMessage(tr("Head markers set; Edit ▸ Undo takes them back"), ui::kStatusMessageMs);
          });
  connect(m_headMarkersBar, &ui::HeadMarkersProposalBar::chooseRequested, this, &MainWindow::editReferenceMarkers);
  layout->addWidget(m_headMarkersBar);
  layout->addWidget(m_view3d, 1);
  return area;
}

bool MainWindow::changeReferenceMarkers(std::vector<Eigen::Index> markers)
{
  std::sort(markers.begin(), markers.end());
  markers.erase(std::unique(markers.begin(), markers.end()), markers.end());
  if (markers == m_document->referenceMarkers())
    return false;  // an edit that changes nothing pushes nothing
  m_document->undoStack()->push(new ui::SetReferenceMarkersCommand(*m_document, std::move(markers)));
  return true;
}

void MainWindow::editReferenceMarkers()
{
  if (!m_document->hasTake())
    return;
  ui::ReferenceMarkersDialog dialog(*m_document, this);
  if (dialog.exec() != QDialog::Accepted)
    return;
  if (!changeReferenceMarkers(dialog.chosen()))
    statusBar()->showMessage(tr("Reference markers unchanged"), ui::kStatusMessageMs);
}

void MainWindow::setSelectedAsReferenceMarkers()
{
  if (m_document->selection().size() < 3) {
    statusBar()->showMessage(tr("Select at least three head-mounted markers first"), ui::kStatusMessageMs);
    return;
  }
  if (!changeReferenceMarkers(m_document->selection()))
    statusBar()->showMessage(tr("The selected markers already are the reference markers"), ui::kStatusMessageMs);
}

void MainWindow::createMarkerMenu()
{
  QMenu* markers = menuBar()->addMenu(tr("&Marker"));
  markers->addAction(tr("&Delete Markers"), QKeySequence(Qt::CTRL | Qt::Key_Delete), m_markerEdits,
                     &ui::MarkerEditActions::deleteMarkers)
      ->setToolTip(tr("Remove the selected markers from the take (undoable)"));
  markers->addAction(tr("Add &Averaged Marker…"), QKeySequence(Qt::CTRL | Qt::Key_M), m_markerEdits,
                     &ui::MarkerEditActions::addAveragedMarker)
      ->setToolTip(tr("A virtual marker at the mean of the selected markers"));
  markers->addAction(tr("&Swap Over Range"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_X), m_markerEdits,
                     &ui::MarkerEditActions::swapOverRange)
      ->setToolTip(tr("Exchange the data of the two selected markers over the selected frame range"));
  markers->addSeparator();
  QAction* reference = markers->addAction(tr("&Reference Markers…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R),
                                          this, &MainWindow::editReferenceMarkers);
  reference->setObjectName(QStringLiteral("referenceMarkersAction"));
  reference->setToolTip(tr("The head-mounted markers that head stabilization, layout planning and the face mesh use"));
  markers->addAction(tr("Set Selected as Reference &Markers"), this, &MainWindow::setSelectedAsReferenceMarkers)
      ->setToolTip(tr("Make the selected markers (at least three) the take's reference markers (undoable)"));
  markers->addSeparator();
  markers->addAction(tr("&Hide Selected"), QKeySequence(Qt::Key_H), this,
                     [this] { m_document->setHidden(m_document->selection(), true); });
  markers->addAction(tr("Show &All"), QKeySequence(Qt::SHIFT | Qt::Key_H), this,
                     [this] { m_document->showAllMarkers(); });
}

void MainWindow::createLabelMenu()
{
  QMenu* label = menuBar()->addMenu(tr("&Label"));
  label->addAction(tr("&Track and Label"), QKeySequence(Qt::CTRL | Qt::Key_T), m_labelling,
                   &ui::LabellingActions::trackAndLabel)
      ->setToolTip(tr("Re-track the unlabelled points and give them the labels of the take's labelled markers"));
  label->addAction(tr("Fix &Swaps…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F), m_labelling,
                   &ui::LabellingActions::reviewSwaps)
      ->setToolTip(tr("Find frames where two labels exchange and repair the ones you accept"));
  QAction* assign = label->addAction(tr("&Assign Label by Clicking"));
  assign->setShortcut(QKeySequence(Qt::Key_A));
  assign->setCheckable(true);
  assign->setToolTip(tr("Select a marker in the table, then click a point in the 3D view to give it that label"));
  connect(assign, &QAction::toggled, this, [this](bool on) {
    m_view3d->setLabellingMode(on);
    statusBar()->showMessage(on ? tr("Labelling: select a marker in the table, then click the point that is it")
                                : QString(),
                             on ? 0 : 1);
  });
  connect(m_view3d, &ui::MarkerView3d::labelPointClicked, m_markerEdits, &ui::MarkerEditActions::assignLabel);
}

QString MainWindow::openFile(const QString& path, bool quiet)
{
  // Read on a worker (a long take takes seconds); the UI thread only installs the result.
  ui::TakeDocument::ReadResult read;
  QString error;
  try {
    if (!ui::runJob(this, tr("Opening %1…").arg(QFileInfo(path).fileName()),
                    [&](const JobControl&) { read = ui::TakeDocument::read(path); }))
      return tr("Cancelled");
    m_document->open(std::move(read), path);
  } catch (const std::exception& e) {  // a failed read leaves the open take as it was
    error = QString::fromStdString(e.what());
  }
  if (!error.isEmpty()) {
    if (!quiet)
      QMessageBox::critical(this, tr("Cannot open file"), error);
    return error;
  }
  m_confirmedOverwrite = false;
  addRecent(path);
  QSettings().setValue(QStringLiteral("lastFolder"), QFileInfo(path).absolutePath());
  showReadWarnings(!quiet && m_document->isIncomplete());
  updateTitle();
  return {};
}

void MainWindow::showReadWarnings(bool askToAcknowledge)
{
  const auto& warnings = m_document->loadWarnings();
  m_warningsButton->setVisible(!warnings.empty());
  m_warningsButton->setText(m_document->isIncomplete()
                                ? tr("⚠ Incomplete: %n warning(s)", nullptr, static_cast<int>(warnings.size()))
                                : tr("⚠ %n warning(s)", nullptr, static_cast<int>(warnings.size())));
  m_warningsButton->setToolTip(tr("Show every warning from reading the file"));
  if (askToAcknowledge)
    openReadWarnings();
}

void MainWindow::openReadWarnings()
{
  auto toList = [](const std::vector<std::string>& texts) {
    QStringList list;
    for (const std::string& text : texts)
      list << QString::fromStdString(text);
    return list;
  };
  ui::ReadWarningsDialog dialog(QFileInfo(m_document->filePath()).fileName(), toList(m_document->loadWarnings()),
                                toList(m_document->dataLossWarnings()), this);
  dialog.exec();
}

void MainWindow::openDialog()
{
  if (!confirmDiscard())
    return;
  const QString path = QFileDialog::getOpenFileName(this, tr("Open take"), QSettings().value("lastFolder").toString(),
                                                    tr(kOpenFilter));
  if (!path.isEmpty())
    openFile(path);
}

bool MainWindow::save()
{
  const QString path = m_document->filePath();
  if (path.isEmpty())
    return saveAs();
  if (!m_confirmedOverwrite) {
    const auto answer = QMessageBox::question(
        this, tr("Overwrite the original?"),
        tr("Save over %1? The original capture is replaced by the edited take.").arg(QFileInfo(path).fileName()),
        QMessageBox::Save | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer != QMessageBox::Save)
      return false;
    m_confirmedOverwrite = true;
  }
  const QString error = m_document->save(path);
  if (!error.isEmpty())
    QMessageBox::critical(this, tr("Cannot save"), error);
  return error.isEmpty();
}

bool MainWindow::saveAs()
{
  const QString path = QFileDialog::getSaveFileName(this, tr("Save take as"), m_document->filePath(),
                                                    tr("C3D (*.c3d);;TRC (*.trc)"));
  if (path.isEmpty())
    return false;
  const QString error = m_document->save(path);
  if (!error.isEmpty()) {
    QMessageBox::critical(this, tr("Cannot save"), error);
    return false;
  }
  m_confirmedOverwrite = true;  // the user chose this file
  addRecent(path);
  showSavedMessage(tr("Saved %1").arg(path), path);
  return true;
}

void MainWindow::showSavedMessage(const QString& message, const QString& path)
{
  const std::string leftOut = leftOutOnWriting(m_document->take(), formatFromPath(path.toStdString()));
  if (leftOut.empty())
    statusBar()->showMessage(message, ui::kStatusMessageMs);
  else  // data the file does not hold: shown longer, and not only in passing
    statusBar()->showMessage(tr("%1 — note: %2").arg(message, QString::fromStdString(leftOut)),
                             3 * ui::kStatusMessageMs);
}

QString MainWindow::saveCleaningPreset(const QString& path, bool withHeadMarkers)
{
  CleanOptions options = m_cleaning->cleanOptions();
  if (withHeadMarkers)
    options.stabilizeLabels = m_document->referenceLabels();
  try {
    writeFileAtomically(path.toStdString(), cleanPresetJson(options));
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

void MainWindow::saveCleaningPresetDialog()
{
  QFileDialog dialog(this, tr("Save Cleaning Preset"), QFileInfo(m_document->filePath()).absolutePath(),
                     tr("Cleaning presets (*.json)"));
  dialog.setAcceptMode(QFileDialog::AcceptSave);
  dialog.setDefaultSuffix(QStringLiteral("json"));
  dialog.setOption(QFileDialog::DontUseNativeDialog);  // a native dialog takes no extra box
  auto* withHeadMarkers = new QCheckBox(tr("Include this take's head markers (%1)")
                                            .arg(m_document->referenceMarkers().empty()
                                                     ? tr("none chosen")
                                                     : joinLabels(m_document->referenceLabels())),
                                        &dialog);
  withHeadMarkers->setObjectName(QStringLiteral("includeHeadMarkers"));
  withHeadMarkers->setToolTip(tr("A preset carries cleaning options; head markers belong to a take. Include them "
                                 "only when every take the preset is for names its head markers the same way: "
                                 "a take without them then fails with that reason."));
  withHeadMarkers->setEnabled(!m_document->referenceMarkers().empty());
  if (auto* grid = qobject_cast<QGridLayout*>(dialog.layout()))
    grid->addWidget(withHeadMarkers, grid->rowCount(), 0, 1, -1);
  if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
    return;
  const QString path = dialog.selectedFiles().front();
  const QString error = saveCleaningPreset(path, withHeadMarkers->isChecked());
  if (!error.isEmpty())
    QMessageBox::warning(this, tr("Save Cleaning Preset"), tr("The preset was not saved: %1").arg(error));
  else
    statusBar()->showMessage(tr("Saved the cleaning preset %1").arg(path), ui::kStatusMessageMs);
}

QString MainWindow::loadCleaningPreset(const QString& path)
{
  CleanOptions options;
  try {
    options = readCleanPreset(path.toStdString());
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  const QStringList off = m_cleaning->loadCleanOptions(options);
  showDock(QStringLiteral("cleaningDock"));
  QString message = tr("Loaded the cleaning preset %1 into the Cleaning panel; nothing changes the take until Apply")
                        .arg(QFileInfo(path).fileName());
  if (!off.isEmpty())
    message += tr("; it turns off %1 (left as they were)").arg(off.join(QStringLiteral(", ")));
  if (!options.stabilizeLabels.empty())
    message += tr("; its head markers (%1) are not this take's: the take keeps its own")
                   .arg(joinLabels(options.stabilizeLabels));
  statusBar()->showMessage(message, 2 * ui::kStatusMessageMs);
  return {};
}

void MainWindow::loadCleaningPresetDialog()
{
  const QString path = QFileDialog::getOpenFileName(this, tr("Load Cleaning Preset"),
                                                    QFileInfo(m_document->filePath()).absolutePath(),
                                                    tr("Cleaning presets (*.json);;All files (*)"));
  if (path.isEmpty())
    return;
  if (const QString error = loadCleaningPreset(path); !error.isEmpty())
    QMessageBox::warning(this, tr("Load Cleaning Preset"), tr("The preset was not loaded: %1").arg(error));
}

void MainWindow::exportDialog()
{
  const QString path = QFileDialog::getSaveFileName(this, tr("Export"), QFileInfo(m_document->filePath()).absolutePath(),
                                                    tr("C3D (*.c3d);;TRC (*.trc);;CSV (*.csv);;BVH (*.bvh);;FBX markers (*.fbx)"));
  if (path.isEmpty())
    return;
  const QString error = m_document->save(path, false);
  if (!error.isEmpty())
    QMessageBox::critical(this, tr("Cannot export"), error);
  else
    showSavedMessage(tr("Exported %1").arg(path), path);
}

bool MainWindow::confirmDiscard()
{
  if (!m_document->isModified())
    return true;
  const auto answer = QMessageBox::warning(this, tr("Unsaved edits"), tr("The take has unsaved edits. Save them?"),
                                           QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
  if (answer == QMessageBox::Save)
    return save();
  return answer == QMessageBox::Discard;
}

void MainWindow::updateTitle()
{
  const QString name =
      m_document->filePath().isEmpty() ? tr("Untitled") : QFileInfo(m_document->filePath()).fileName();
  setWindowTitle(m_document->isIncomplete() ? tr("%1 (incomplete)[*] — Mocap Studio").arg(name)
                                            : tr("%1[*] — Mocap Studio").arg(name));
  setWindowModified(m_document->isModified());
}

void MainWindow::addRecent(const QString& path)
{
  const QString absolute = QFileInfo(path).absoluteFilePath();
  m_recent.removeAll(absolute);
  m_recent.prepend(absolute);
  while (m_recent.size() > kMaxRecent)
    m_recent.removeLast();
  QSettings().setValue(QStringLiteral("recentFiles"), m_recent);
  updateRecentMenu();
}

void MainWindow::updateRecentMenu()
{
  m_recentMenu->clear();
  for (const QString& path : m_recent)
    m_recentMenu->addAction(QFileInfo(path).fileName(), this, [this, path] {
      if (confirmDiscard())
        openFile(path);
    })->setToolTip(path);
  m_recentMenu->setEnabled(!m_recent.isEmpty());
}

bool MainWindow::offerRecovery()
{
  for (const ui::RecoveryFile& file : ui::Autosave::leftovers()) {
    const QString name =
        file.originalPath.isEmpty() ? tr("an untitled take") : QFileInfo(file.originalPath).fileName();
    const auto answer = QMessageBox::question(
        this, tr("Recover unsaved edits?"),
        tr("Mocap Studio did not close normally. Unsaved edits of %1 were kept at %2. Recover them?")
            .arg(name, QLocale().toString(file.written, QLocale::ShortFormat)),
        QMessageBox::Yes | QMessageBox::Discard | QMessageBox::Ignore, QMessageBox::Yes);
    if (answer == QMessageBox::Ignore)
      continue;  // ask again next time
    if (answer == QMessageBox::Discard) {
      ui::Autosave::remove(file);
      continue;
    }
    try {
      m_document->setTake(readTake(file.path.toStdString()), file.originalPath);
    } catch (const std::exception& e) {
      QMessageBox::critical(this, tr("Cannot recover"), QString::fromStdString(e.what()));
      continue;
    }
    m_document->markModified();
    m_confirmedOverwrite = false;
    restoreSession(file.session);
    // Our own recovery copy first, then the old one goes: the edits are never only in memory.
    if (m_autosave->saveNow().isEmpty())
      ui::Autosave::remove(file);
    statusBar()->showMessage(tr("Recovered unsaved edits of %1; save them to keep them").arg(name), 2 * ui::kStatusMessageMs);
    return true;
  }
  return false;
}

QVariantMap MainWindow::recoverySession() const
{
  QVariantMap session = m_session->recoveryState();
  session.insert(QStringLiteral("windowState"), saveState());
  return session;
}

void MainWindow::restoreSession(const QVariantMap& session)
{
  restoreState(session.value(QStringLiteral("windowState")).toByteArray());
  if (session.value(QStringLiteral("mesh")).toString().isEmpty())
    return;
  const QString error = m_session->restoreRecoveryState(session);
  m_faceMeshDock->show();
  if (!error.isEmpty())
    statusBar()->showMessage(tr("The face mesh of the recovered session could not be restored: %1").arg(error),
                             2 * ui::kStatusMessageMs);
}

bool MainWindow::showDock(const QString& name)
{
  for (QDockWidget* dock : findChildren<QDockWidget*>())
    if (dock->objectName().compare(name, Qt::CaseInsensitive) == 0 ||
        dock->windowTitle().compare(name, Qt::CaseInsensitive) == 0) {
      dock->show();
      dock->raise();
      // A tabified dock shown while the window was hidden may not take its tab's place on
      // raise(); its tab then brings it forward.
      for (QTabBar* tabs : findChildren<QTabBar*>())
        for (int i = 0; i < tabs->count(); ++i)
          if (tabs->tabText(i) == dock->windowTitle() && tabs->isVisible())
            tabs->setCurrentIndex(i);
      return true;
    }
  return false;
}

int MainWindow::selectLabels(const QStringList& labels)
{
  std::vector<Eigen::Index> markers;
  for (const QString& label : labels)
    if (const auto index = m_document->take().markerIndex(label.toStdString()))
      markers.push_back(*index);
  const int found = static_cast<int>(markers.size());
  m_document->setSelection(std::move(markers));
  return found;
}

void MainWindow::syncTableSelection()
{
  m_syncingSelection = true;
  QItemSelection selection;
  for (Eigen::Index m : m_document->selection()) {
    const QModelIndex source = m_tableModel->index(static_cast<int>(m), 0);
    const QModelIndex row = m_proxy->mapFromSource(source);
    selection.select(row, row.siblingAtColumn(ui::MarkerTableModel::ColumnCount - 1));
  }
  m_table->selectionModel()->select(selection, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
  if (!m_document->selection().empty())
    m_table->scrollTo(m_proxy->mapFromSource(m_tableModel->index(static_cast<int>(m_document->selection().front()), 0)));
  m_syncingSelection = false;
}

void MainWindow::closeEvent(QCloseEvent* event)
{
  if (ui::jobRunning()) {  // the worker reads the document: it must end before the window does
    statusBar()->showMessage(tr("Cancel the running job before closing"), ui::kStatusMessageMs);
    event->ignore();
    return;
  }
  if (!confirmDiscard()) {
    event->ignore();
    return;
  }
  writeSettings();
  event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
  if (event->mimeData()->hasUrls())
    event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
  const auto urls = event->mimeData()->urls();
  if (!urls.isEmpty() && urls.front().isLocalFile() && confirmDiscard())
    openFile(urls.front().toLocalFile());
}

void MainWindow::readSettings()
{
  QSettings settings;
  m_recent = settings.value(QStringLiteral("recentFiles")).toStringList();
  if (!restoreGeometry(settings.value(QStringLiteral("geometry")).toByteArray()))
    applyFirstRunLayout();
  restoreState(settings.value(QStringLiteral("windowState")).toByteArray());
  updateRecentMenu();
  applyPreferences(ui::Preferences::load());
  // The layout is saved shortly after every change (dock moved, shown, resized), not only on a
  // clean quit, so a crash keeps it.
  m_layoutSaver = new QTimer(this);
  m_layoutSaver->setSingleShot(true);
  m_layoutSaver->setInterval(500);
  connect(m_layoutSaver, &QTimer::timeout, this, &MainWindow::writeSettings);
  for (QDockWidget* dock : findChildren<QDockWidget*>()) {
    connect(dock, &QDockWidget::dockLocationChanged, m_layoutSaver, qOverload<>(&QTimer::start));
    connect(dock, &QDockWidget::visibilityChanged, m_layoutSaver, qOverload<>(&QTimer::start));
    connect(dock, &QDockWidget::topLevelChanged, m_layoutSaver, qOverload<>(&QTimer::start));
  }
}

ui::ManualWindow* MainWindow::showManual()
{
  if (!m_manual)
    m_manual = new ui::ManualWindow(this);
  m_manual->show();
  m_manual->raise();
  m_manual->activateWindow();
  return m_manual;
}

QDockWidget* MainWindow::addDock(const QString& title, const QString& objectName, QWidget* content,
                                 Qt::DockWidgetArea area, DockContent kind)
{
  auto* dock = new QDockWidget(title, this);
  dock->setObjectName(objectName);
  if (kind == DockContent::Scrolls) {
    // A panel scrolls rather than making the window taller or wider than the screen (e.g. 1280×800):
    // the window's minimum size is the sum of its docks' minimum sizes.
    auto* scroll = new QScrollArea(dock);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(content);
    dock->setWidget(scroll);
  } else {
    dock->setWidget(content);
  }
  addDockWidget(area, dock);
  return dock;
}

void MainWindow::applyFirstRunLayout()
{
  const QScreen* screen = QGuiApplication::primaryScreen();
  if (!screen)
    return;
  const QRect available = screen->availableGeometry();
  const QSize size(available.width() * 85 / 100, available.height() * 85 / 100);
  resize(size);
  move(available.center() - QPoint(size.width() / 2, size.height() / 2));
  m_firstRun = true;  // the docks are proportioned once the window is shown (see showEvent)
}

void MainWindow::proportionDocks()
{
  // Side docks share at most half the width and the curves under the view a quarter of the height;
  // the 3D view keeps the rest. (Panels scroll, so on a small screen these shares are what counts.)
  QList<QDockWidget*> sideDocks, bottomDocks;
  QList<int> widths, heights;
  for (QDockWidget* dock : findChildren<QDockWidget*>()) {
    if (!dock->isVisible() || dock->isFloating())
      continue;
    const Qt::DockWidgetArea area = dockWidgetArea(dock);
    if (area == Qt::LeftDockWidgetArea || area == Qt::RightDockWidgetArea) {
      sideDocks.append(dock);
      widths.append(width() * (area == Qt::LeftDockWidgetArea ? 12 : 30) / 100);
    } else if (area == Qt::BottomDockWidgetArea) {
      bottomDocks.append(dock);
      heights.append(height() * 26 / 100);
    }
  }
  resizeDocks(sideDocks, widths, Qt::Horizontal);
  resizeDocks(bottomDocks, heights, Qt::Vertical);
}

void MainWindow::showEvent(QShowEvent* event)
{
  QMainWindow::showEvent(event);
  if (std::exchange(m_firstRun, false))
    proportionDocks();
}

void MainWindow::resizeEvent(QResizeEvent* event)
{
  QMainWindow::resizeEvent(event);
  if (m_layoutSaver)
    m_layoutSaver->start();
}

void MainWindow::writeSettings() const
{
  QSettings settings;
  settings.setValue(QStringLiteral("geometry"), saveGeometry());
  settings.setValue(QStringLiteral("windowState"), saveState());
}

} // namespace mocap::studio
