#include "main_window.h"

#include "dock_layout.h"
#include "language.h"

#include "actions/animation_export.h"
#include "actions/cleaning_preset_actions.h"
#include "actions/labelling_actions.h"
#include "actions/language_menu.h"
#include "actions/head_stabilized_view_action.h"
#include "actions/marker_edit_actions.h"
#include "actions/marker_menus.h"
#include "actions/option_toggle.h"
#include "actions/reference_marker_actions.h"
#include "actions/recovery_offer.h"
#include "actions/review_video_export.h"
#include "actions/take_file_actions.h"
#include "actions/take_units_menu.h"
#include "actions/transport_shortcuts.h"
#include "actions/view_option_actions.h"

#include "actions/actor_actions.h"
#include "dialogs/job_dialog.h"
#include "dialogs/manual_window.h"
#include "dialogs/preferences_dialog.h"
#include "dialogs/read_warnings_button.h"
#include "dialogs/read_warnings_dialog.h"
#include "document/autosave.h"
#include "document/studio_options.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "document/view_state.h"
#include "panels/cleaning_panel.h"
#include "document/blendshape_solve_model.h"
#include "panels/blendshape_solve_panel.h"
#include "panels/dock_tab_titles.h"
#include "panels/face_mesh_panel.h"
#include "panels/gap_fill_step.h"
#include "panels/gap_list_panel.h"
#include "panels/head_markers_proposal_bar.h"
#include "panels/head_stabilization_step.h"
#include "panels/history_panel.h"
#include "panels/layout_planning_panel.h"
#include "panels/live_stream_panel.h"
#include "panels/marker_table_panel.h"
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
#include "views/frame_status_label.h"
#include "views/model_outputs_note.h"
#include "views/status_timeout.h"
#include "views/review_scene.h"
#include "views/session_scene.h"
#include "views/timeline_widget.h"
#include "views/wheel_guard.h"

#include "mocap/model/data_loss_record.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QTimer>
#include <QVBoxLayout>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>

#include <utility>

namespace mocap::studio {

namespace {
const QString kWindowStateKey = QStringLiteral("windowState");  // in the recovery description
} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_session(new ui::StudioSession(this)), m_document(&m_session->document())
{
  setAcceptDrops(true);
  ui::WheelGuard::install();
  m_session->followOptions();
  m_view3d = new ui::MarkerView3d(*m_document, this);
  m_view3d->observe(m_session->view());
  // The session's face mesh and posed rig, drawn with the markers; the docks only observe them.
  m_sessionScene = new ui::SessionScene(*m_session, m_view3d->scene(), this);
  m_sessionScene->observe(m_session->view());
  m_view3d->addLayers(*m_sessionScene);
  m_referenceMarkers = new ui::ReferenceMarkerActions(*m_document, *this, this);
  setCentralWidget(centralArea());
  m_timeline = new ui::TimelineWidget(*m_document, this);
  auto* timelineBar = new QToolBar(tr("Timeline"), this);
  timelineBar->setObjectName(QStringLiteral("timelineBar"));
  timelineBar->addWidget(m_timeline);
  timelineBar->setMovable(false);
  addToolBar(Qt::BottomToolBarArea, timelineBar);
  m_markerEdits = new ui::MarkerEditActions(*m_document, *this, this);
  m_labelling = new ui::LabellingActions(*m_document, *this, this);
  QStatusBar* status = statusBar();
  connect(m_markerEdits, &ui::MarkerEditActions::message, status, &QStatusBar::showMessage);
  connect(m_labelling, &ui::LabellingActions::message, status, &QStatusBar::showMessage);
  connect(m_referenceMarkers, &ui::ReferenceMarkerActions::message, status, &QStatusBar::showMessage);
  m_files = new ui::TakeFileActions(*m_document, m_session->options(), *this, this);
  connect(m_files, &ui::TakeFileActions::message, status, &QStatusBar::showMessage);
  createDocks();
  ui::keepDockTabTitlesWhole(*this);  // six tabbed docks in a narrow side dock stay readable
  m_cleaningPresets = new ui::CleaningPresetActions(
      *m_document, *this,
      {[this] { return m_cleaning->cleanOptions(); },
       [this](const CleanOptions& options) { return m_cleaning->loadCleanOptions(options); }},
      this);
  connect(m_cleaningPresets, &ui::CleaningPresetActions::message, status, &QStatusBar::showMessage);
  connect(m_cleaningPresets, &ui::CleaningPresetActions::loaded, this,
          [this] { (void)showDock(QStringLiteral("cleaningDock")); });
  createActions();
  statusBar()->addPermanentWidget(new ui::FrameStatusLabel(*m_document, this));
  m_warningsButton = new ui::ReadWarningsButton(*m_document, this);
  statusBar()->addPermanentWidget(m_warningsButton);
  connect(m_files, &ui::TakeFileActions::opened, this, [this](const QString&, bool askToAcknowledge) {
    m_warningsButton->showWarnings(askToAcknowledge);
    updateTitle();
  });
  statusBar()->addPermanentWidget(new ui::ModelOutputsNote(*m_document, this));
  connect(m_timeline, &ui::TimelineWidget::message, this, [this](const QString& text) {
    statusBar()->showMessage(text, ui::kStatusMessageMs);
  });

  connect(m_document, &ui::TakeDocument::modifiedChanged, this, &MainWindow::updateTitle);
  connect(m_document, &ui::TakeDocument::filePathChanged, this, &MainWindow::updateTitle);
  m_autosave = new ui::Autosave(*m_document, {}, this);
  connect(m_autosave, &ui::Autosave::failed, this, [this](const QString& message) {
    statusBar()->showMessage(tr("Autosave failed: %1").arg(message), 2 * ui::kStatusMessageMs);
  });
  // The session's state goes with the take; the window adds its layout.
  m_autosave->setStateProvider([this] { return m_session->saveState(); });
  m_autosave->setSessionProvider([this] { return QVariantMap{{kWindowStateKey, saveState()}}; });
  m_session->options().autosaveMinutes.follow(m_autosave,
                                              [this](int minutes) { m_autosave->setInterval(minutes * 60 * 1000); });
  readSettings();
  updateTitle();
}

MainWindow::~MainWindow() = default;

void MainWindow::createDocks()
{
  m_table = new ui::MarkerTablePanel(*m_document, this);
  addDock(*this, tr("Markers"), QStringLiteral("markersDock"), m_table, Qt::LeftDockWidgetArea, DockContent::Fixed);

  m_curves = new ui::CurveView(*m_document, this);
  m_curves->observe(m_session->view());
  QDockWidget* curveDock =
      addDock(*this, tr("Curves"), QStringLiteral("curvesDock"), m_curves, Qt::BottomDockWidgetArea, DockContent::Fixed);

  m_cleaning = new ui::CleaningPanel(*m_document, this);
  m_cleaning->addStep(new ui::SpikeStep(*m_document, m_cleaning));
  auto* gapFillStep = new ui::GapFillStep(*m_document, m_cleaning);
  m_cleaning->addStep(gapFillStep);
  auto* smoothingStep = new ui::SmoothingStep(m_cleaning);
  smoothingStep->observe(m_session->view());
  m_cleaning->addStep(smoothingStep);
  // Last: its preview moves every marker, not something to compute on every open.
  m_cleaning->addStep(new ui::HeadStabilizationStep(*m_document, m_cleaning));
  QDockWidget* historyDock = addDock(*this, tr("History"), QStringLiteral("historyDock"),
                                     new ui::HistoryPanel(*m_document, this), Qt::RightDockWidgetArea);
  historyDock->hide();  // View ▸ History shows it (clicking an entry undoes or redoes to it)

  QDockWidget* cleaningDock = addDock(*this, tr("Cleaning"), QStringLiteral("cleaningDock"), m_cleaning, Qt::RightDockWidgetArea);

  // Marker layout planning (issue 7): its selected layout is highlighted in the 3D view.
  m_layoutPlanning = new ui::LayoutPlanningPanel(*m_session, this);
  QDockWidget* layoutDock =
      addDock(*this, tr("Layout planning"), QStringLiteral("layoutPlanningDock"), m_layoutPlanning, Qt::RightDockWidgetArea,
              DockContent::Fixed);  // scrolls its form itself, under a fixed Run row
  tabifyDockWidget(cleaningDock, layoutDock);
  m_gapList = new ui::GapListPanel(*m_document, this);  // issue 13: every gap, filled one by one or checked
  QDockWidget* gapDock = addDock(*this, tr("Gaps"), QStringLiteral("gapListDock"), m_gapList, Qt::RightDockWidgetArea);
  tabifyDockWidget(cleaningDock, gapDock);
  connect(m_gapList, &ui::GapListPanel::frameRangeRequested, m_curves, &ui::CurveView::setVisibleRange);
  // One set of fill rules: the Gaps dock fills past the Cleaning panel's only when told to.
  m_gapList->setFillRules(gapFillStep->currentOptions());
  connect(gapFillStep, &ui::CleaningStep::changed, m_gapList,
          [this, gapFillStep] { m_gapList->setFillRules(gapFillStep->currentOptions()); });
  cleaningDock->raise();
  // The highlight shows only while the dock is on screen: leaving the panel (another tab raised,
  // the dock closed) gives the 3D view its sample-state colours back, returning shows it again; a
  // plan set while its tab is behind another (a recovered session's) waits for the tab.
  auto showLayout = [this, layoutDock] {
    ui::LayoutHighlight shown = dockInFront(*layoutDock) ? m_session->layoutPlan().highlight() : ui::LayoutHighlight{};
    m_session->view().setLayoutHighlight(std::move(shown.kept), std::move(shown.reference));
  };
  connect(&m_session->layoutPlan(), &ui::LayoutPlanModel::changed, this, showLayout);
  connect(&m_session->layoutPlan(), &ui::LayoutPlanModel::highlightChanged, this, showLayout);
  connect(layoutDock, &QDockWidget::visibilityChanged, this, showLayout);
  // Every panel shows the take's reference markers and sends the user to the one editor.
  connect(m_layoutPlanning, &ui::LayoutPlanningPanel::editReferenceMarkersRequested, m_referenceMarkers,
          &ui::ReferenceMarkerActions::edit);
  connect(m_cleaning->step<ui::HeadStabilizationStep>(), &ui::HeadStabilizationStep::editReferenceMarkersRequested,
          m_referenceMarkers, &ui::ReferenceMarkerActions::edit);
  m_faceMesh = new ui::FaceMeshPanel(*m_session, *m_view3d, m_sessionScene->faceMesh(), this);
  connect(m_faceMesh, &ui::FaceMeshPanel::editReferenceMarkersRequested, m_referenceMarkers,
          &ui::ReferenceMarkerActions::edit);
  m_faceMeshDock = addDock(*this, tr("Face Mesh"), QStringLiteral("faceMeshDock"), m_faceMesh, Qt::RightDockWidgetArea);
  tabifyDockWidget(cleaningDock, m_faceMeshDock);
  m_faceMeshDock->hide();  // View ▸ Face Mesh shows it

  m_blendshapeSolve = new ui::BlendshapeSolvePanel(*m_session, this);
  connect(m_blendshapeSolve, &ui::BlendshapeSolvePanel::message, statusBar(), &QStatusBar::showMessage);
  m_blendshapeDock =
      addDock(*this, tr("Blendshape Solve"), QStringLiteral("blendshapeSolveDock"), m_blendshapeSolve, Qt::RightDockWidgetArea);
  tabifyDockWidget(cleaningDock, m_blendshapeDock);
  m_blendshapeDock->hide();  // View ▸ Blendshape Solve shows it

  m_referenceVideo = new ui::ReferenceVideoPanel(*m_session, this);
  QDockWidget* videoDock =
      addDock(*this, tr("Reference Video"), QStringLiteral("referenceVideoDock"), m_referenceVideo, Qt::RightDockWidgetArea);
  tabifyDockWidget(cleaningDock, videoDock);
  videoDock->hide();  // View ▸ Reference Video shows it, and opening a take that remembers videos
  connect(&m_session->referenceVideos(), &ui::ReferenceVideos::restored, this, [this](int count) {
    if (count > 0)
      (void)showDock(QStringLiteral("referenceVideoDock"));
  });

  QDockWidget* streamDock = addDock(*this, tr("Live Stream"), QStringLiteral("liveStreamDock"),
                                    new ui::LiveStreamPanel(*m_session, this), Qt::RightDockWidgetArea);
  tabifyDockWidget(cleaningDock, streamDock);
  streamDock->hide();  // View ▸ Live Stream shows it

  m_weights = new ui::WeightCurveView(*m_document, m_session->blendshapes(), this);
  m_weightsDock =
      addDock(*this, tr("Weights"), QStringLiteral("weightsDock"), m_weights, Qt::BottomDockWidgetArea, DockContent::Fixed);
  tabifyDockWidget(curveDock, m_weightsDock);
  m_weightsDock->hide();  // shown with the first solve, or from View ▸ Weights
  connect(m_blendshapeSolve, &ui::BlendshapeSolvePanel::solveFinished, this, [this](const QString& error) {
    if (!error.isEmpty())
      return;
    // The first solve of a rig: show its curves, and frame the posed rig with the markers.
    if (!m_weightsDock->isVisible())
      m_session->view().resetCamera();
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
  m_session->view().resetCamera();  // frame the mesh with the markers
  return error;
}

ui::ReviewSource MainWindow::reviewSource() const
{
  ui::ReviewSource source;
  source.session = m_session;
  source.settings = ui::shownSettings(*m_view3d, m_session->view());
  return source;
}

void MainWindow::createActions()
{
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&Open…"), QKeySequence::Open, m_files, &ui::TakeFileActions::openWithDialog);
  m_files->followRecentFiles(*file->addMenu(tr("Open &Recent")));
  ui::StudioOptions& options = m_session->options();
  QAction* keepRig = ui::addOptionToggle(*file, tr("&Keep Face Rig for the Next Take"), options.keepRig);
  keepRig->setObjectName(QStringLiteral("keepRigAction"));
  keepRig->setToolTip(tr("Opening another take keeps the face mesh, its marker binding and the blendshape rig (the "
                         "actor's), bound to the markers the new take has; off, every take starts without them"));
  connect(m_session, &ui::StudioSession::takeContextReset, this, [this](bool rigKept) {
    if (rigKept)
      statusBar()->showMessage(tr("Face rig kept for this take: %1").arg(m_session->faceMesh().bindingSummary()),
                               2 * ui::kStatusMessageMs);
  });
  file->addSeparator();
  file->addAction(tr("&Save"), QKeySequence::Save, m_files, &ui::TakeFileActions::save);
  file->addAction(tr("Save &As…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S), m_files, &ui::TakeFileActions::saveAs);
  file->addAction(tr("&Export…"), QKeySequence(Qt::CTRL | Qt::Key_E), m_files, &ui::TakeFileActions::exportWithDialog);
  file->addAction(tr("Export Ani&mation…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E), this,
                  [this] { ui::exportAnimation(*m_session, *this); });
  file->addAction(tr("Export Re&view Video…"), QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_E), this,
                  &MainWindow::exportReviewVideo);
  file->addAction(tr("Export Ri&g…"), this, [this] { m_blendshapeSolve->openExportDialog(ui::RigExportFormat::Fbx); })
      ->setToolTip(tr("The solved rig as FBX or glTF, or its curves as CSV, through a retarget map (Blendshape Solve)"));
  file->addAction(tr("Save &Cleaning Preset…"), m_cleaningPresets, &ui::CleaningPresetActions::saveWithDialog);
  file->addAction(tr("&Load Cleaning Preset…"), m_cleaningPresets, &ui::CleaningPresetActions::loadWithDialog)
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
  edit->addAction(tr("&Rename Marker…"), QKeySequence(Qt::Key_F2), m_table, &ui::MarkerTablePanel::editCurrentLabel);
  ui::addTakeUnitsMenu(*edit, *m_document);
  edit->addSeparator();
  QAction* preferences = edit->addAction(tr("&Preferences…"), QKeySequence(Qt::CTRL | Qt::Key_Comma), this, [this] {
    ui::editPreferences(m_session->options(), availableLanguages(), availableLanguageNames(), defaultLanguage(), this);
  });
  preferences->setMenuRole(QAction::PreferencesRole);

  ui::addMarkerMenu(*menuBar(), *m_document, *m_markerEdits, *m_referenceMarkers);
  ui::addLabelMenu(*menuBar(), *m_labelling, *m_markerEdits, *m_view3d,
                   [this](const QString& text, int timeoutMs) { statusBar()->showMessage(text, timeoutMs); });
  menuBar()->addMenu(m_blendshapeSolve->actors().createMenu(this));

  m_viewMenu = menuBar()->addMenu(tr("&View"));
  ui::addViewOptionActions(*m_viewMenu, options, m_session->view());
  ui::addLanguageMenu(*m_viewMenu->addMenu(tr("&Language")), options.language, availableLanguages(),
                      availableLanguageNames(), defaultLanguage(), *this);
  m_viewMenu->addSeparator();
  for (QDockWidget* dock : findChildren<QDockWidget*>())
    m_viewMenu->addAction(dock->toggleViewAction());
  m_viewMenu->addSeparator();
  m_headStabilizedView = new ui::HeadStabilizedViewAction(*m_document, m_session->view(), *this, this);
  connect(m_headStabilizedView, &ui::HeadStabilizedViewAction::message, statusBar(), &QStatusBar::showMessage);
  m_viewMenu->addAction(m_headStabilizedView->action());

  ui::addTransportShortcuts(*this, *m_document, *m_timeline);

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
}

void MainWindow::exportReviewVideo()
{
  ui::exportReviewVideo(reviewSource(), *this,
                        [this](const QString& text, int timeoutMs) { statusBar()->showMessage(text, timeoutMs); });
}

QWidget* MainWindow::centralArea()
{
  auto* area = new QWidget(this);
  auto* layout = new QVBoxLayout(area);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  m_headMarkersBar = new ui::HeadMarkersProposalBar(*m_document, area);
  connect(m_headMarkersBar, &ui::HeadMarkersProposalBar::acceptRequested, m_referenceMarkers,
          &ui::ReferenceMarkerActions::acceptProposed);
  connect(m_headMarkersBar, &ui::HeadMarkersProposalBar::chooseRequested, m_referenceMarkers,
          &ui::ReferenceMarkerActions::edit);
  layout->addWidget(m_headMarkersBar);
  layout->addWidget(m_view3d, 1);
  return area;
}

QString MainWindow::openFile(const QString& path, bool quiet)
{
  return m_files->open(path, quiet);
}

void MainWindow::updateTitle()
{
  const QString name =
      m_document->filePath().isEmpty() ? tr("Untitled") : QFileInfo(m_document->filePath()).fileName();
  const QString dataLoss = ui::dataLossInWords(dataLossKinds(m_document->dataLossWarnings()));
  setWindowTitle(dataLoss.isEmpty() ? tr("%1[*] — Mocap Studio").arg(name)
                                    : tr("%1 (%2)[*] — Mocap Studio").arg(name, dataLoss));
  setWindowModified(m_document->isModified());
}

bool MainWindow::offerRecovery(bool ask)
{
  const std::optional<ui::RecoveredTake> recovered = ui::offerRecovery(
      *m_session, *m_autosave, *this,
      [this](const QVariantMap& window) {
        m_files->forgetOverwriteConfirmation();
        restoreState(window.value(kWindowStateKey).toByteArray());
      },
      ask);
  if (!recovered)
    return false;
  if (m_session->faceMesh().hasMesh()) {
    m_faceMeshDock->show();
    m_session->view().resetCamera();  // frame the mesh and rig with the markers, as on loading them
  }
  // What could not be restored is said, not asked about: the take's edits are back either way.
  const QString problems = QString(recovered->problems).replace(QLatin1Char('\n'), QStringLiteral("; "));
  statusBar()->showMessage(
      problems.isEmpty() ? tr("Recovered unsaved edits of %1; save them to keep them").arg(recovered->name)
                         : tr("Recovered unsaved edits of %1; not restored: %2").arg(recovered->name, problems),
      2 * ui::kStatusMessageMs);
  return true;
}

bool MainWindow::showDock(const QString& name)
{
  return raiseDock(*this, name);
}

int MainWindow::selectLabels(const QStringList& labels)
{
  return m_document->selectLabels(labels);
}

void MainWindow::closeEvent(QCloseEvent* event)
{
  if (ui::jobRunning()) {  // the worker reads the document: it must end before the window does
    statusBar()->showMessage(tr("Cancel the running job before closing"), ui::kStatusMessageMs);
    event->ignore();
    return;
  }
  if (!m_files->confirmDiscard()) {
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
  if (!urls.isEmpty() && urls.front().isLocalFile() && m_files->confirmDiscard())
    openFile(urls.front().toLocalFile());
}

void MainWindow::readSettings()
{
  const ui::StudioOptions& options = m_session->options();
  if (!restoreGeometry(options.windowGeometry))
    m_firstRun = placeFirstRunWindow(*this);  // the docks are proportioned once shown (showEvent)
  restoreState(options.windowState);
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

QTableView* MainWindow::markerTable() const
{
  return m_table;
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

void MainWindow::showEvent(QShowEvent* event)
{
  QMainWindow::showEvent(event);
  if (std::exchange(m_firstRun, false))
    proportionDocks(*this);
}

void MainWindow::resizeEvent(QResizeEvent* event)
{
  QMainWindow::resizeEvent(event);
  if (m_layoutSaver)
    m_layoutSaver->start();
}

void MainWindow::writeSettings() const
{
  m_session->options().windowGeometry = saveGeometry();
  m_session->options().windowState = saveState();
}

} // namespace mocap::studio
