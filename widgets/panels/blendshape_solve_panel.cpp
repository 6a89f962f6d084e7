#include "panels/blendshape_solve_panel.h"

#include "actions/actor_actions.h"
#include "actions/live_link_recording_import.h"
#include "actions/weight_edit_actions.h"
#include "dialogs/live_link_open_dialog.h"
#include "dialogs/remembered_file_dialog.h"
#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/job_runner.h"
#include "document/live_link_recording.h"
#include "document/session_option.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "document/view_state.h"
#include "panels/flow_layout.h"
#include "panels/job_progress_row.h"
#include "panels/retarget_section.h"
#include "panels/status_line.h"
#include "views/status_timeout.h"

#include "mocap/io/rig_io.h"
#include "mocap/io/weight_output.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

namespace {

const QString kGroup = QStringLiteral("blendshapeSolve/");

QString settingKey(const char* name)
{
  return kGroup + QLatin1String(name);
}

/// The panel's remembered settings, typed ("blendshapeSolve/…").
struct BlendshapeSolveSettings
{
  SessionOption<int> method{settingKey("method"), static_cast<int>(BlendshapeSolveOptions{}.method)};
  SessionOption<bool> autoLambda{settingKey("autoLambda"), true};
  SessionOption<double> lambda{settingKey("lambda"), 0.001};
  SessionOption<double> smoothness{settingKey("smoothness"), BlendshapeSolveOptions{}.smoothness};
  SessionOption<double> sparsity{settingKey("sparsity"), BlendshapeSolveOptions{}.sparsity};
  SessionOption<double> scale{settingKey("scale"), 0.8};
  SessionOption<double> cutoff{settingKey("cutoff"), 6.0};
  SessionOption<bool> show{settingKey("show"), true};
  SessionOption<bool> beside{settingKey("beside"), true};
};


RigLoad readRigInBackground(const QString& path, const QString& shapeFolder)
{
  RigLoad load;
  load.path = path;
  load.shapeFolder = shapeFolder;
  try {
    load.rig = std::make_shared<const BlendshapeRig>(readRig(path.toStdString(), shapeFolder.toStdString()));
  } catch (const std::exception& e) {  // nothing may throw across the event loop
    load.error = QString::fromStdString(e.what());
  }
  return load;
}

SolveRun solveInBackground(const std::shared_ptr<const BlendshapeRig>& rig, const MeshBinding& binding,
                           const Take& take, const BlendshapeSolveOptions& options, const JobControl& control)
{
  SolveRun run;
  run.options = options;
  try {
    std::optional<Take> inActorUnits;  // an actor's neutral is in its own units, as `mocap solve --actor` converts
    if (options.actor && take.units() != options.actor->units) {
      inActorUnits = take;
      inActorUnits->convertUnits(options.actor->units);
    }
    const Take& solved = inActorUnits ? *inActorUnits : take;
    const BlendshapeSolver solver(*rig, binding, solved, options);
    run.result = solver.solve(solved, {}, control);
    run.markers = solver.markers().size();
    run.setupSeconds = solver.setupSeconds();
  } catch (const JobCancelled&) {
    run.result = {};  // cancelled: no weights, no error
  } catch (const std::exception& e) {
    run.error = QString::fromStdString(e.what());
  }
  return run;
}

/// The peak weight of every shape, for the list.
Eigen::VectorXd peaks(const Eigen::MatrixXd& weights)
{
  return weights.rows() > 0 ? Eigen::VectorXd(weights.colwise().maxCoeff().transpose())
                            : Eigen::VectorXd::Zero(weights.cols());
}

} // namespace

BlendshapeSolvePanel::BlendshapeSolvePanel(StudioSession& session, QWidget* parent)
    : QWidget(parent), m_session(session), m_document(session.document()), m_faceMesh(session.faceMesh()),
      m_model(session.blendshapes()), m_edits(new WeightEditActions(m_document, m_model, this)), m_actors(new ActorActions(session, *this, this)),
      m_jobs(new JobRunner(this))
{
  TakeDocument& document = m_document;
  buildUi();
  readSettings();
  connect(&m_model, &BlendshapeSolveModel::rigChanged, this, &BlendshapeSolvePanel::showRig);
  connect(&session, &StudioSession::takeContextReset, this, &BlendshapeSolvePanel::onTakeContextReset);
  connect(&m_model, &BlendshapeSolveModel::selectedShapesChanged, this, &BlendshapeSolvePanel::onModelSelectionChanged);
  connect(&m_model, &BlendshapeSolveModel::weightsEdited, this, &BlendshapeSolvePanel::fillShapeList);
  connect(&document, &TakeDocument::takeReset, &m_model, &BlendshapeSolveModel::clearResult);
  connect(m_actors, &ActorActions::message, this, [this](const QString& text, int timeoutMs) {
    showStatus(text);
    emit message(text, timeoutMs);
  });
  // Weights solved before an edit of the take no longer follow it: say so (they stay, as a product).
  const auto stale = [this] {
    if (m_model.hasResult() && !busy())
      showStatus(tr("The take has changed since this solve; Solve again to update the weights."));
  };
  connect(&document, &TakeDocument::samplesChanged, this, stale);
  connect(&document, &TakeDocument::markersChanged, this, stale);
}

BlendshapeSolvePanel::~BlendshapeSolvePanel() = default;  // the runner stops and awaits its job

void BlendshapeSolvePanel::buildUi()
{
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(buildRigBox());
  layout->addWidget(buildSolveBox());
  layout->addWidget(buildShapesBox(), 1);
  layout->addWidget(buildDisplayBox());
  m_retarget = new RetargetSection(m_document, m_model, m_model.retargetMap(), this);
  layout->addWidget(m_retarget);
  m_status = new QLabel(this);
  m_status->setWordWrap(true);
  m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(m_status);
  showStatus(tr("Load a rig, bind the markers to its neutral in the Face Mesh panel, then Solve."));
}

QWidget* BlendshapeSolvePanel::buildRigBox()
{
  auto* box = new QGroupBox(tr("Rig"), this);
  auto* rows = new QVBoxLayout(box);
  m_rigLabel = new QLabel(tr("No rig"), box);
  m_rigLabel->setWordWrap(true);
  rows->addWidget(m_rigLabel);
  auto* buttons = new FlowLayout;  // rows of buttons wrap in a narrow dock
  auto* gltf = new QPushButton(tr("Load glTF Rig…"), box);
  gltf->setToolTip(tr("A .glb or .gltf with the neutral mesh and one morph target per shape"));
  connect(gltf, &QPushButton::clicked, this, &BlendshapeSolvePanel::loadGltfDialog);
  auto* obj = new QPushButton(tr("Load OBJ Rig…"), box);
  obj->setToolTip(tr("A neutral OBJ/PLY and a folder with one OBJ per shape, named after it"));
  connect(obj, &QPushButton::clicked, this, &BlendshapeSolvePanel::loadObjDialog);
  buttons->addWidget(gltf);
  buttons->addWidget(obj);
  rows->addLayout(buttons);
  return box;
}

QWidget* BlendshapeSolvePanel::buildSolveBox()
{
  auto* box = new QGroupBox(tr("Solve"), this);
  auto* form = new QFormLayout(box);
  m_method = new QComboBox(box);
  m_method->setObjectName(QStringLiteral("solveMethod"));
  m_method->addItem(tr("Temporal (smooth over time)"), static_cast<int>(BlendshapeSolveMethod::Temporal));
  m_method->addItem(tr("Ridge (per frame)"), static_cast<int>(BlendshapeSolveMethod::Ridge));
  m_method->addItem(tr("Bounded least squares (per frame)"), static_cast<int>(BlendshapeSolveMethod::Bvls));
  form->addRow(tr("Method:"), m_method);
  auto* lambdaRow = new QHBoxLayout;
  m_autoLambda = new QCheckBox(tr("Automatic (GCV)"), box);
  m_lambda = new QDoubleSpinBox(box);
  m_lambda->setDecimals(6);
  m_lambda->setRange(0.0, 1e6);
  m_lambda->setSingleStep(0.001);
  m_lambda->setToolTip(tr("Ridge weight λ, relative to the shapes' mean squared motion"));
  lambdaRow->addWidget(m_autoLambda);
  lambdaRow->addWidget(m_lambda, 1);
  form->addRow(tr("λ:"), lambdaRow);
  m_smoothness = new QDoubleSpinBox(box);
  m_smoothness->setDecimals(3);
  m_smoothness->setRange(0.0, 1e6);
  m_smoothness->setToolTip(tr("Weight of the weights' second differences over time, as at 100 Hz"));
  form->addRow(tr("Smoothness:"), m_smoothness);
  m_sparsity = new QDoubleSpinBox(box);
  m_sparsity->setDecimals(4);
  m_sparsity->setRange(0.0, 1e3);
  m_sparsity->setSingleStep(0.001);
  m_sparsity->setToolTip(tr("L1 weight pulling unused shapes to zero"));
  form->addRow(tr("Sparsity:"), m_sparsity);
  connect(m_method, &QComboBox::currentIndexChanged, this, &BlendshapeSolvePanel::updateMethodFields);
  connect(m_autoLambda, &QCheckBox::toggled, this, &BlendshapeSolvePanel::updateMethodFields);
  for (QDoubleSpinBox* spin : {m_lambda, m_smoothness, m_sparsity})
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this] { writeSettings(); });
  m_solve = new QPushButton(tr("Solve"), box);
  m_solve->setToolTip(tr("Solve every frame of the take to the rig's weights (on a worker; Cancel stops it)"));
  connect(m_solve, &QPushButton::clicked, this, [this] { (void)solve(); });
  form->addRow(m_solve);
  connect(m_jobs, &JobRunner::cancelled, this, [this] { showStatus(tr("Cancelling…")); });
  form->addRow(new JobProgressRow(*m_jobs, box));
  return box;
}

QWidget* BlendshapeSolvePanel::buildShapesBox()
{
  auto* box = new QGroupBox(tr("Shapes"), this);
  auto* rows = new QVBoxLayout(box);
  m_filter = new QLineEdit(box);
  m_filter->setPlaceholderText(tr("Filter shapes (e.g. mouth)"));
  m_filter->setClearButtonEnabled(true);
  connect(m_filter, &QLineEdit::textChanged, this, &BlendshapeSolvePanel::applyShapeFilter);
  rows->addWidget(m_filter);
  m_shapes = new QListWidget(box);
  m_shapes->setObjectName(QStringLiteral("shapeList"));
  m_shapes->setSelectionMode(QAbstractItemView::ExtendedSelection);
  m_shapes->setMinimumHeight(180);  // a rig has tens of shapes: show a good part of them
  m_shapes->setToolTip(tr("Selected shapes are drawn in the Weights view and edited below"));
  connect(m_shapes, &QListWidget::itemSelectionChanged, this, &BlendshapeSolvePanel::onListSelectionChanged);
  rows->addWidget(m_shapes, 1);

  auto* edits = new QFormLayout;
  auto* scaleRow = new QHBoxLayout;
  m_scaleFactor = new QDoubleSpinBox(box);
  m_scaleFactor->setRange(0.0, 10.0);
  m_scaleFactor->setDecimals(2);
  m_scaleFactor->setSingleStep(0.05);
  auto* scale = new QPushButton(tr("Scale"), box);
  connect(scale, &QPushButton::clicked, this, [this] { showEditResult(m_edits->scale(m_scaleFactor->value())); });
  auto* zero = new QPushButton(tr("Zero"), box);
  connect(zero, &QPushButton::clicked, this, [this] { showEditResult(m_edits->zero()); });
  scaleRow->addWidget(m_scaleFactor, 1);
  scaleRow->addWidget(scale);
  scaleRow->addWidget(zero);
  edits->addRow(tr("Scale by:"), scaleRow);
  auto* smoothRow = new QHBoxLayout;
  m_cutoff = new QDoubleSpinBox(box);
  m_cutoff->setRange(0.1, 100.0);
  m_cutoff->setDecimals(1);
  m_cutoff->setSuffix(tr(" Hz"));
  auto* smooth = new QPushButton(tr("Smooth"), box);
  connect(smooth, &QPushButton::clicked, this, [this] { showEditResult(m_edits->smooth(m_cutoff->value())); });
  smoothRow->addWidget(m_cutoff, 1);
  smoothRow->addWidget(smooth);
  edits->addRow(tr("Low-pass:"), smoothRow);
  for (QDoubleSpinBox* spin : {m_scaleFactor, m_cutoff})
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this] { writeSettings(); });
  rows->addLayout(edits);
  auto* hint = new QLabel(tr("Edits apply to the selected shapes over the frame range selected on the curves "
                             "(Shift-drag), or the whole take; Ctrl+Z undoes them."),
                          box);
  hint->setWordWrap(true);
  hint->setStyleSheet(QStringLiteral("color: gray;"));
  rows->addWidget(hint);
  return box;
}

QWidget* BlendshapeSolvePanel::buildDisplayBox()
{
  auto* box = new QGroupBox(tr("Display and export"), this);
  auto* rows = new QVBoxLayout(box);
  m_show = new QCheckBox(tr("Show the solved rig in the 3D view"), box);
  connect(m_show, &QCheckBox::toggled, this, [this](bool on) {
    m_session.view().setRigShown(on);  // the scene follows
    writeSettings();
  });
  m_beside = new QCheckBox(tr("Beside the markers (else over them)"), box);
  connect(m_beside, &QCheckBox::toggled, this, [this](bool on) {
    m_session.view().setRigBeside(on);
    writeSettings();
  });
  rows->addWidget(m_show);
  rows->addWidget(m_beside);
  auto* buttons = new FlowLayout;
  m_openLiveLink = new QPushButton(tr("Open Live Link Recording…"), box);
  m_openLiveLink->setToolTip(tr("A Live Link Face CSV as the rig's weight curves, through a map (undoable)"));
  connect(m_openLiveLink, &QPushButton::clicked, this, &BlendshapeSolvePanel::openLiveLinkDialog);
  m_exportCsv = new QPushButton(tr("Export Weights…"), box);
  m_exportCsv->setToolTip(tr("Weight curves as CSV: one column per shape (plain or Live Link Face layout)"));
  connect(m_exportCsv, &QPushButton::clicked, this, [this] { openExportDialog(RigExportFormat::WeightsCsv); });
  m_exportGlb = new QPushButton(tr("Export Rig…"), box);
  m_exportGlb->setToolTip(tr("The rig with its blend shapes and the weights as animation curves, FBX or glTF "
                             "(Unreal, Maya, MotionBuilder, Blender, Unity), through a retarget map, keys reduced"));
  connect(m_exportGlb, &QPushButton::clicked, this, [this] { openExportDialog(RigExportFormat::Fbx); });
  auto* openRow = new QHBoxLayout;  // a row of its own: three buttons overflow a narrow dock
  openRow->addWidget(m_openLiveLink);
  openRow->addStretch();
  rows->addLayout(openRow);
  buttons->addWidget(m_exportCsv);
  buttons->addWidget(m_exportGlb);
  rows->addLayout(buttons);
  connect(&m_model, &BlendshapeSolveModel::resultChanged, this, [this] {
    m_exportCsv->setEnabled(m_model.hasResult());
    m_exportGlb->setEnabled(m_model.hasResult());
  });
  connect(&m_model, &BlendshapeSolveModel::rigChanged, this, [this] { m_openLiveLink->setEnabled(m_model.hasRig()); });
  m_exportCsv->setEnabled(false);
  m_exportGlb->setEnabled(false);
  m_openLiveLink->setEnabled(false);
  return box;
}

void BlendshapeSolvePanel::readSettings()
{
  m_loadingSettings = true;
  const BlendshapeSolveSettings settings;
  m_method->setCurrentIndex(std::max(0, m_method->findData(settings.method.get())));
  m_autoLambda->setChecked(settings.autoLambda);
  m_lambda->setValue(settings.lambda);
  m_smoothness->setValue(settings.smoothness);
  m_sparsity->setValue(settings.sparsity);
  m_scaleFactor->setValue(settings.scale);
  m_cutoff->setValue(settings.cutoff);
  m_show->setChecked(settings.show);
  m_beside->setChecked(settings.beside);
  m_loadingSettings = false;
  m_session.view().setRigShown(m_show->isChecked());
  m_session.view().setRigBeside(m_beside->isChecked());
  updateMethodFields();
}

void BlendshapeSolvePanel::writeSettings() const
{
  if (m_loadingSettings)
    return;
  BlendshapeSolveSettings settings;
  settings.method = m_method->currentData().toInt();
  settings.autoLambda = m_autoLambda->isChecked();
  settings.lambda = m_lambda->value();
  settings.smoothness = m_smoothness->value();
  settings.sparsity = m_sparsity->value();
  settings.scale = m_scaleFactor->value();
  settings.cutoff = m_cutoff->value();
  settings.show = m_show->isChecked();
  settings.beside = m_beside->isChecked();
}

void BlendshapeSolvePanel::updateMethodFields()
{
  const auto method = static_cast<BlendshapeSolveMethod>(m_method->currentData().toInt());
  m_autoLambda->setEnabled(method != BlendshapeSolveMethod::Bvls);
  m_lambda->setEnabled(method != BlendshapeSolveMethod::Bvls && !m_autoLambda->isChecked());
  m_smoothness->setEnabled(method == BlendshapeSolveMethod::Temporal);
  writeSettings();
}

BlendshapeSolveOptions BlendshapeSolvePanel::optionsFromUi() const
{
  BlendshapeSolveOptions options;
  options.method = static_cast<BlendshapeSolveMethod>(m_method->currentData().toInt());
  if (options.method != BlendshapeSolveMethod::Bvls && !m_autoLambda->isChecked())
    options.lambda = m_lambda->value();
  options.smoothness = m_smoothness->value();
  options.sparsity = m_sparsity->value();
  // The neutral frame is the face mesh's: the binding was made on it.
  options.neutralFrame = m_faceMesh.options().neutralFrame;
  options.scale = m_faceMesh.options().scale;
  options.actor = m_model.actor();
  return options;
}

bool BlendshapeSolvePanel::busy() const
{
  return m_jobs->running();
}

void BlendshapeSolvePanel::finishJob()
{
  m_jobs->wait();
}

QString BlendshapeSolvePanel::loadRig(const QString& path, const QString& shapeFolder)
{
  if (busy()) {
    showStatus(tr("Wait for the running job, or cancel it."), true);
    return m_status->text();
  }
  showStatus(tr("Reading %1…").arg(QFileInfo(path).fileName()));
  m_jobs->start([path, shapeFolder](const JobControl&) { return readRigInBackground(path, shapeFolder); },
                [this](const RigLoad& load) { onRigLoaded(load); });
  return {};
}

void BlendshapeSolvePanel::onRigLoaded(const RigLoad& load)
{
  if (!load.error.isEmpty()) {
    showStatus(tr("Cannot read the rig %1: %2").arg(QFileInfo(load.path).fileName(), load.error), true);
    emit rigLoaded(m_status->text());
    return;
  }
  m_session.setBlendshapeRig(load.rig, load.path, load.shapeFolder);  // its neutral becomes the face mesh
  showStatus(m_faceMesh.binding().markers.empty()
                 ? tr("Rig loaded. Bind the markers to its neutral in the Face Mesh panel (Auto-Bind or Load Binding), then Solve.")
                 : tr("Rig loaded. Solve when ready."));
  emit rigLoaded({});
}

void BlendshapeSolvePanel::showRig()
{
  if (const auto& rig = m_model.rig())
    m_rigLabel->setText(tr("%1: %n shape(s), %2 vertices", nullptr, static_cast<int>(rig->shapeCount()))
                            .arg(QFileInfo(m_model.rigPath()).fileName())
                            .arg(static_cast<qlonglong>(rig->neutral.vertexCount())));
  else
    m_rigLabel->setText(tr("No rig"));
  fillShapeList();
}

void BlendshapeSolvePanel::onTakeContextReset(bool rigKept)
{
  if (rigKept && m_model.hasRig())
    showStatus(tr("Rig kept from the previous take: %1. Solve when ready.").arg(m_faceMesh.bindingSummary()),
               m_faceMesh.binding().markers.size() < 3);
  else
    showStatus(tr("Load a rig, bind the markers to its neutral in the Face Mesh panel, then Solve."));
}

QString BlendshapeSolvePanel::solve()
{
  QString problem;
  const FaceMeshModel& face = m_faceMesh;
  if (busy())
    problem = tr("A job is already running.");
  else if (!m_document.hasTake())
    problem = tr("Open a take first.");
  else if (!m_model.hasRig())
    problem = tr("Load a rig first.");
  else if (face.mesh().vertexCount() != m_model.rig()->neutral.vertexCount())
    problem = tr("The Face Mesh panel shows another mesh than this rig's neutral; load the rig again.");
  else if (face.binding().markers.empty())
    problem = tr("Bind the markers to the rig's neutral in the Face Mesh panel first (Auto-Bind or Load Binding).");
  if (!problem.isEmpty()) {
    showStatus(problem, true);
    return problem;
  }
  showStatus(tr("Solving…"));
  m_solve->setEnabled(false);
  m_jobs->start(
      [rig = m_model.rig(), binding = face.binding(), take = face.rigTake(), options = optionsFromUi()](
          const JobControl& control) { return solveInBackground(rig, binding, take, options, control); },
      [this](SolveRun run) { onSolved(std::move(run)); });
  return {};
}

void BlendshapeSolvePanel::cancel()
{
  m_jobs->cancel();
}

void BlendshapeSolvePanel::onSolved(SolveRun run)
{
  m_solve->setEnabled(true);
  if (!run.error.isEmpty()) {
    showStatus(tr("Solve failed: %1").arg(run.error), true);
    emit solveFinished(m_status->text());
    return;
  }
  if (run.result.weights.rows() == 0) {
    showStatus(tr("Cancelled; the weights are as they were."));
    emit solveFinished(tr("cancelled"));
    return;
  }
  const BlendshapeSolveResult& r = run.result;
  double sum = 0.0, worst = 0.0;
  int solved = 0;
  for (const double e : r.residual)
    if (std::isfinite(e)) {
      sum += e;
      worst = std::max(worst, e);
      ++solved;
    }
  const auto held = static_cast<int>(std::count(r.held.begin(), r.held.end(), true));
  const QString method = QString::fromUtf8(blendshapeSolveMethodName(run.options.method).data());
  QString text = tr("Solved %1 frames from %2 markers (%3, λ %4%5) in %6 s; marker residual %7 mm mean, %8 mm max.")
                     .arg(r.weights.rows())
                     .arg(run.markers)
                     .arg(method)
                     .arg(r.lambda, 0, 'g', 3)
                     .arg(r.lambdaChosen ? tr(" by GCV") : QString())
                     .arg(run.setupSeconds + r.solveSeconds, 0, 'f', 2)
                     .arg(solved > 0 ? sum / solved : 0.0, 0, 'f', 2)
                     .arg(worst, 0, 'f', 2);
  if (held > 0)
    text += QLatin1Char('\n') + tr("Warning: %n frame(s) had too few markers and hold the previous frame's weights "
                                   "(shaded red in the Weights view).",
                                   nullptr, held);
  const BlendshapeSolveOptions options = run.options;
  m_model.setResult(std::move(run.result), options);
  fillShapeList();
  showStatus(text, held > 0);
  emit solveFinished({});
}

void BlendshapeSolvePanel::fillShapeList()
{
  const QSignalBlocker blocker(m_shapes);
  m_shapes->clear();
  if (!m_model.hasRig())
    return;
  const Eigen::VectorXd peak = peaks(m_model.weights());
  for (Eigen::Index s = 0; s < m_model.rig()->shapeCount(); ++s) {
    QString text = m_model.shapeName(s);
    if (m_model.hasResult())
      text += tr("  (peak %1)").arg(peak(s), 0, 'f', 2);
    auto* item = new QListWidgetItem(text, m_shapes);
    item->setData(Qt::UserRole, static_cast<qlonglong>(s));
    if (m_model.hasResult() && peak(s) < 0.01)
      item->setForeground(QColor(130, 130, 130));  // never used in this take
  }
  applyShapeFilter();
  m_syncingSelection = true;
  onModelSelectionChanged();
  m_syncingSelection = false;
}

void BlendshapeSolvePanel::applyShapeFilter()
{
  const QString filter = m_filter->text().trimmed();
  for (int i = 0; i < m_shapes->count(); ++i) {
    QListWidgetItem* item = m_shapes->item(i);
    item->setHidden(!filter.isEmpty() && !m_model.shapeName(item->data(Qt::UserRole).toLongLong())
                                              .contains(filter, Qt::CaseInsensitive));
  }
}

void BlendshapeSolvePanel::onListSelectionChanged()
{
  if (m_syncingSelection)
    return;
  std::vector<Eigen::Index> shapes;
  for (const QListWidgetItem* item : m_shapes->selectedItems())
    shapes.push_back(static_cast<Eigen::Index>(item->data(Qt::UserRole).toLongLong()));
  m_syncingSelection = true;
  m_model.setSelectedShapes(std::move(shapes));
  m_syncingSelection = false;
}

void BlendshapeSolvePanel::onModelSelectionChanged()
{
  if (m_syncingSelection && sender() == &m_model)
    return;
  const QSignalBlocker blocker(m_shapes);
  const auto& selected = m_model.selectedShapes();
  for (int i = 0; i < m_shapes->count(); ++i) {
    QListWidgetItem* item = m_shapes->item(i);
    const auto shape = static_cast<Eigen::Index>(item->data(Qt::UserRole).toLongLong());
    item->setSelected(std::binary_search(selected.begin(), selected.end(), shape));
  }
  if (!selected.empty())
    for (int i = 0; i < m_shapes->count(); ++i)
      if (m_shapes->item(i)->isSelected()) {
        m_shapes->scrollToItem(m_shapes->item(i));
        break;
      }
}

void BlendshapeSolvePanel::showEditResult(const QString& why)
{
  if (why.isEmpty())
    return;
  showStatus(why, true);
  emit message(why, kStatusMessageMs);
}

RigExportSource BlendshapeSolvePanel::exportSource() const
{
  const Take& take = m_document.take();
  RigExportSource source;
  source.rig = m_model.rig();
  source.weights = m_model.weights();
  source.baseName = QFileInfo(m_document.filePath()).completeBaseName();
  if (const std::optional<ReadWeightCurves>& read = m_model.readCurves()) {
    source.frameRate = read->frameRate;  // the recording's own timing, timecode kept
    source.startSeconds = read->startSeconds;
    source.headRotation = read->headRotation;
    source.baseName = QFileInfo(read->path).completeBaseName();
  } else {
    source.frameRate = take.frameRate();
    source.firstFrame = take.firstFrame();
    source.headRotation = solvedHeadRotation(m_session);
  }
  const RetargetMapModel& map = m_model.retargetMap();
  if (map.map()) {
    source.sectionMap = map.map();
    source.sectionMapName = map.name();
    source.sectionMapEdited = map.edited();
  }
  return source;
}

QString BlendshapeSolvePanel::writeCurves(const QString& path, const WeightOutput& options)
{
  if (!m_model.hasResult())
    return tr("Solve the take first.");
  try {
    (void)writeWeightOutput(path.toStdString(), *m_model.rig(), m_model.weights(), options);
  } catch (const std::exception& e) {
    showStatus(tr("Cannot write the weights: %1").arg(QString::fromStdString(e.what())), true);
    return m_status->text();
  }
  showStatus(tr("Wrote %1").arg(QFileInfo(path).fileName()));
  return {};
}

QString BlendshapeSolvePanel::exportCsv(const QString& path, bool liveLink)
{
  WeightOutput options = rigExportOptions(exportSource());
  options.liveLink = liveLink;
  return writeCurves(path, options);
}

QString BlendshapeSolvePanel::exportGlb(const QString& path)
{
  return writeCurves(path, rigExportOptions(exportSource()));
}

void BlendshapeSolvePanel::openExportDialog(RigExportFormat format)
{
  if (!m_model.hasResult()) {
    showEditResult(tr("Solve the take, or open a Live Link recording, first: there are no curves to export."));
    return;
  }
  RigExportDialog dialog(exportSource(), this);
  // The weights button keeps a remembered Live Link choice; otherwise each button picks its kind.
  const bool csv = format == RigExportFormat::WeightsCsv;
  const bool rememberedCsv = dialog.format() == RigExportFormat::WeightsCsv || dialog.format() == RigExportFormat::LiveLinkCsv;
  if (csv != rememberedCsv)
    dialog.setFormat(format);
  dialog.exec();
  if (!dialog.statusText().isEmpty())
    showStatus(dialog.statusText());
}

QString BlendshapeSolvePanel::openLiveLinkRecording(const QString& path, const std::optional<std::string>& map)
{
  const QString error = ui::openLiveLinkRecording(m_document, m_model, path, map);
  if (!error.isEmpty()) {
    showStatus(tr("Cannot open the recording: %1").arg(error), true);
    return m_status->text();
  }
  const ReadWeightCurves& read = *m_model.readCurves();
  QString text = tr("Opened %1: %n sample(s) at %2 Hz from %3 as the curves of %4 shapes; exports keep its rate and timecode.",
                    nullptr, static_cast<int>(m_model.weights().rows()))
                     .arg(QFileInfo(path).fileName())
                     .arg(read.frameRate, 0, 'g', 6)
                     .arg(read.firstTimecode)
                     .arg(m_model.weights().cols());
  if (read.recordedRate != read.frameRate)
    text += QLatin1Char(' ') + tr("Recorded at %1 Hz: resampled to the take's rate.").arg(read.recordedRate, 0, 'g', 6);
  showStatus(text);
  return {};
}

QString BlendshapeSolvePanel::statusText() const
{
  return m_status->text();
}

void BlendshapeSolvePanel::showStatus(const QString& text, bool error)
{
  showStatusLine(*m_status, text, error);
}

void BlendshapeSolvePanel::loadGltfDialog()
{
  const QString path =
      openFileOfGroup(this, tr("Load glTF rig"), kGroup, tr("glTF rigs (*.glb *.gltf);;All files (*)"));
  if (!path.isEmpty())
    (void)loadRig(path);
}

void BlendshapeSolvePanel::loadObjDialog()
{
  const QString neutral =
      openFileOfGroup(this, tr("Load the rig's neutral mesh"), kGroup, tr("Meshes (*.obj *.ply);;All files (*)"));
  if (neutral.isEmpty())
    return;
  const QString folder = QFileDialog::getExistingDirectory(this, tr("The folder with one OBJ per shape"),
                                                           QFileInfo(neutral).absolutePath());
  if (folder.isEmpty())
    return;
  (void)loadRig(neutral, folder);
}

void BlendshapeSolvePanel::openLiveLinkDialog()
{
  LiveLinkOpenDialog dialog(this);
  if (dialog.exec() == QDialog::Accepted)
    (void)openLiveLinkRecording(dialog.recordingPath(), dialog.map());
}

} // namespace mocap::ui
