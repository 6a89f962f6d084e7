#include "panels/face_mesh_panel.h"

#include "commands/rebind_marker_command.h"
#include "dialogs/remembered_file_dialog.h"
#include "document/face_mesh_model.h"
#include "document/session_option.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "document/view_state.h"
#include "panels/flow_layout.h"
#include "panels/reference_markers_row.h"
#include "panels/status_line.h"
#include "views/face_mesh_scene.h"
#include "views/marker_view_3d.h"
#include "views/mesh_layer.h"
#include "views/vtk_viewport.h"

#include "mocap/deform/face_rig.h"
#include "mocap/base/file_io.h"
#include "mocap/model/marker_set.h"
#include "mocap/io/mesh_io.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QMouseEvent>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QStackedWidget>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mocap::ui {

namespace {

const QString kGroup = QStringLiteral("faceMesh/");
constexpr int kClickSlop = 4;      // pixels a press may move and still count as a click
constexpr int kMarkerRadius = 6;   // pixels around another marker that select it instead

QString settingKey(const char* name)
{
  return kGroup + QLatin1String(name);
}

/// The panel's remembered settings, typed ("faceMesh/…").
struct FaceMeshSettings
{
  SessionOption<int> method{settingKey("method"), 0};
  SessionOption<int> kernel{settingKey("kernel"), 0};
  SessionOption<double> radius{settingKey("radius"), RbfOptions{}.radius};
  SessionOption<bool> regions{settingKey("regions"), false};
  SessionOption<int> weights{settingKey("weights"), static_cast<int>(LaplacianWeights::MeanValue)};
  SessionOption<double> constraintWeight{settingKey("constraintWeight"), LaplacianOptions{}.constraintWeight};
  SessionOption<int> rotations{settingKey("rotations"), 0};
  SessionOption<bool> compare{settingKey("compare"), false};
  SessionOption<bool> edges{settingKey("edges"), false};
  SessionOption<int> opacity{settingKey("opacity"), 60};
};


QString nameText(std::string_view name)
{
  return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
}

} // namespace

FaceMeshPanel::FaceMeshPanel(StudioSession& session, MarkerView3d& view, const FaceMeshScene& scene, QWidget* parent)
    : QWidget(parent), m_document(session.document()), m_view(view), m_model(session.faceMesh()), m_scene(scene),
      m_viewState(session.view()), m_undo(session.undoStack())
{
  TakeDocument& document = m_document;
  buildUi();
  readSettings();
  connect(&m_model, &FaceMeshModel::meshChanged, this, &FaceMeshPanel::updateMeshLabel);
  connect(&m_model, &FaceMeshModel::bindingChanged, this, &FaceMeshPanel::updateBindingSummary);
  connect(&m_model, &FaceMeshModel::rigChanged, this, &FaceMeshPanel::updateRigStatus);
  connect(&m_scene, &FaceMeshScene::deformed, this, [this] { m_timing->setText(timingText()); });
  connect(&document, &TakeDocument::takeReset, this, &FaceMeshPanel::onTakeReset);
  connect(&document, &TakeDocument::selectionChanged, this, &FaceMeshPanel::onSelectionChanged);
  view.viewport()->installEventFilter(this);  // vertex clicks, before the view selects markers
  onTakeReset();
}

FaceMeshPanel::~FaceMeshPanel() = default;

void FaceMeshPanel::buildUi()
{
  auto* layout = new QVBoxLayout(this);

  auto* meshBox = new QGroupBox(tr("Mesh and binding"), this);
  auto* meshLayout = new QVBoxLayout(meshBox);
  m_meshLabel = new QLabel(tr("No mesh"), meshBox);
  m_meshLabel->setWordWrap(true);
  meshLayout->addWidget(m_meshLabel);
  auto* files = new FlowLayout;  // rows of buttons wrap in a narrow dock
  auto* loadMeshButton = new QPushButton(tr("Load Mesh…"), meshBox);
  loadMeshButton->setToolTip(tr("A face mesh as OBJ or PLY, or a glTF rig's neutral"));
  connect(loadMeshButton, &QPushButton::clicked, this, &FaceMeshPanel::loadMeshDialog);
  auto* loadBindingButton = new QPushButton(tr("Load Binding…"), meshBox);
  connect(loadBindingButton, &QPushButton::clicked, this, &FaceMeshPanel::loadBindingDialog);
  auto* saveBindingButton = new QPushButton(tr("Save Binding…"), meshBox);
  connect(saveBindingButton, &QPushButton::clicked, this, &FaceMeshPanel::saveBindingDialog);
  files->addWidget(loadMeshButton);
  files->addWidget(loadBindingButton);
  files->addWidget(saveBindingButton);
  meshLayout->addLayout(files);
  m_bindingLabel = new QLabel(meshBox);
  m_bindingLabel->setWordWrap(true);
  meshLayout->addWidget(m_bindingLabel);
  auto* edit = new FlowLayout;
  auto* autoBindButton = new QPushButton(tr("Auto-Bind"), meshBox);
  autoBindButton->setToolTip(tr("Align the neutral frame to the mesh and bind each marker to its nearest surface "
                                "point (the selected markers when three or more are selected)"));
  connect(autoBindButton, &QPushButton::clicked, this, [this] { (void)autoBind(); });
  m_pick = new QToolButton(meshBox);
  m_pick->setText(tr("Pick Vertex"));
  m_pick->setCheckable(true);
  m_pick->setToolTip(tr("Select a marker, then click the mesh vertex it sits on"));
  connect(m_pick, &QToolButton::toggled, this, [this](bool on) {
    m_status->setText(on ? tr("Select a marker, then click its vertex on the mesh") : QString());
  });
  auto* undo = new QToolButton(meshBox);
  undo->setDefaultAction(m_undo->createUndoAction(this, tr("Undo")));
  auto* redo = new QToolButton(meshBox);
  redo->setDefaultAction(m_undo->createRedoAction(this, tr("Redo")));
  edit->addWidget(autoBindButton);
  edit->addWidget(m_pick);
  edit->addWidget(undo);
  edit->addWidget(redo);
  meshLayout->addLayout(edit);
  layout->addWidget(meshBox);

  auto* rigBox = new QGroupBox(tr("Deformation"), this);
  auto* form = new QFormLayout(rigBox);
  m_reference = new ReferenceMarkersRow(
      m_document, tr("Head motion is removed with these markers before binding and deforming; they are not bound."),
      rigBox);
  connect(m_reference, &ReferenceMarkersRow::editRequested, this, &FaceMeshPanel::editReferenceMarkersRequested);
  form->addRow(tr("Reference markers:"), m_reference);
  m_neutral = new QSpinBox(rigBox);
  m_neutral->setToolTip(tr("The frame whose marker positions are the rest mesh"));
  connect(m_neutral, &QSpinBox::valueChanged, this, &FaceMeshPanel::applyOptions);
  form->addRow(tr("Neutral frame:"), m_neutral);
  m_method = new QComboBox(rigBox);
  m_method->setObjectName(QStringLiteral("method"));
  m_method->addItem(tr("RBF"), static_cast<int>(DeformMethod::Rbf));
  m_method->addItem(tr("Laplacian"), static_cast<int>(DeformMethod::Laplacian));
  form->addRow(tr("Method:"), m_method);

  m_methodPages = new QStackedWidget(rigBox);
  auto* rbfPage = new QWidget(m_methodPages);
  auto* rbfForm = new QFormLayout(rbfPage);
  rbfForm->setContentsMargins(0, 0, 0, 0);
  m_kernel = new QComboBox(rbfPage);
  for (const RbfKernel kernel : {RbfKernel::Exp, RbfKernel::Gaussian, RbfKernel::Biharmonic, RbfKernel::ThinPlate})
    m_kernel->addItem(nameText(rbfKernelName(kernel)), static_cast<int>(kernel));
  rbfForm->addRow(tr("Kernel:"), m_kernel);
  m_radius = new QDoubleSpinBox(rbfPage);
  m_radius->setRange(0.001, 1e6);
  m_radius->setDecimals(3);
  m_radius->setValue(RbfOptions{}.radius);
  m_radius->setToolTip(tr("Kernel radius c, in mesh units"));
  rbfForm->addRow(tr("Radius:"), m_radius);
  m_regions = new QCheckBox(tr("Top, middle and bottom regions"), rbfPage);
  rbfForm->addRow(m_regions);
  auto* lapPage = new QWidget(m_methodPages);
  auto* lapForm = new QFormLayout(lapPage);
  lapForm->setContentsMargins(0, 0, 0, 0);
  m_weights = new QComboBox(lapPage);
  for (const LaplacianWeights w : {LaplacianWeights::Uniform, LaplacianWeights::Cotangent, LaplacianWeights::MeanValue})
    m_weights->addItem(nameText(laplacianWeightsName(w)), static_cast<int>(w));
  m_weights->setCurrentIndex(2);
  lapForm->addRow(tr("Weights:"), m_weights);
  m_constraintWeight = new QDoubleSpinBox(lapPage);
  m_constraintWeight->setRange(0.001, 1e4);
  m_constraintWeight->setDecimals(3);
  m_constraintWeight->setValue(LaplacianOptions{}.constraintWeight);
  lapForm->addRow(tr("Constraint weight:"), m_constraintWeight);
  m_rotations = new QSpinBox(lapPage);
  m_rotations->setRange(0, 10);
  m_rotations->setToolTip(tr("Rotation-aware iterations per frame (0: linear)"));
  lapForm->addRow(tr("Rotations:"), m_rotations);
  m_methodPages->addWidget(rbfPage);
  m_methodPages->addWidget(lapPage);
  form->addRow(m_methodPages);
  m_compare = new QCheckBox(tr("Compare RBF and Laplacian side by side"), rigBox);
  form->addRow(m_compare);
  for (QComboBox* combo : {m_method, m_kernel, m_weights})
    connect(combo, &QComboBox::currentIndexChanged, this, &FaceMeshPanel::applyOptions);
  for (QDoubleSpinBox* spin : {m_radius, m_constraintWeight})
    connect(spin, &QDoubleSpinBox::valueChanged, this, &FaceMeshPanel::applyOptions);
  connect(m_rotations, &QSpinBox::valueChanged, this, &FaceMeshPanel::applyOptions);
  for (QCheckBox* box : {m_regions, m_compare})
    connect(box, &QCheckBox::toggled, this, &FaceMeshPanel::applyOptions);
  layout->addWidget(rigBox);

  auto* lookBox = new QGroupBox(tr("Display"), this);
  auto* look = new QFormLayout(lookBox);
  m_edges = new QCheckBox(tr("Edges"), lookBox);
  connect(m_edges, &QCheckBox::toggled, this, [this](bool on) {
    m_viewState.setMeshEdges(on);  // the scene follows
    writeSettings();
  });
  look->addRow(m_edges);
  m_opacity = new QSlider(Qt::Horizontal, lookBox);
  m_opacity->setRange(10, 100);
  m_opacity->setValue(60);
  connect(m_opacity, &QSlider::valueChanged, this, [this](int percent) {
    m_viewState.setMeshOpacity(percent / 100.0);  // the scene follows
    writeSettings();
  });
  look->addRow(tr("Opacity:"), m_opacity);
  layout->addWidget(lookBox);

  m_timing = new QLabel(this);
  layout->addWidget(m_timing);
  m_status = new QLabel(this);
  m_status->setWordWrap(true);
  m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(m_status);
  layout->addStretch();
  updateBindingSummary();
}

void FaceMeshPanel::readSettings()
{
  m_loadingSettings = true;
  const FaceMeshSettings settings;
  m_method->setCurrentIndex(std::max(0, m_method->findData(settings.method.get())));
  m_kernel->setCurrentIndex(std::max(0, m_kernel->findData(settings.kernel.get())));
  m_radius->setValue(settings.radius);
  m_regions->setChecked(settings.regions);
  m_weights->setCurrentIndex(std::max(0, m_weights->findData(settings.weights.get())));
  m_constraintWeight->setValue(settings.constraintWeight);
  m_rotations->setValue(settings.rotations);
  m_compare->setChecked(settings.compare);
  m_edges->setChecked(settings.edges);
  m_opacity->setValue(settings.opacity);
  m_methodPages->setCurrentIndex(std::max(0, m_method->currentIndex()));
  m_loadingSettings = false;
  m_model.setOptions(optionsFromUi());
  m_model.setCompare(m_compare->isChecked());
}

void FaceMeshPanel::writeSettings() const
{
  if (m_loadingSettings)
    return;
  FaceMeshSettings settings;
  settings.method = m_method->currentData().toInt();
  settings.kernel = m_kernel->currentData().toInt();
  settings.radius = m_radius->value();
  settings.regions = m_regions->isChecked();
  settings.weights = m_weights->currentData().toInt();
  settings.constraintWeight = m_constraintWeight->value();
  settings.rotations = m_rotations->value();
  settings.compare = m_compare->isChecked();
  settings.edges = m_edges->isChecked();
  settings.opacity = m_opacity->value();
}

FaceRigOptions FaceMeshPanel::optionsFromUi() const
{
  FaceRigOptions options;
  options.method = static_cast<DeformMethod>(m_method->currentData().toInt());
  options.rbf.kernel = static_cast<RbfKernel>(m_kernel->currentData().toInt());
  options.rbf.radius = m_radius->value();
  options.rbf.regions = m_regions->isChecked();
  options.laplacian.weights = static_cast<LaplacianWeights>(m_weights->currentData().toInt());
  options.laplacian.constraintWeight = m_constraintWeight->value();
  options.rotations = m_rotations->value();
  if (m_neutral->value() != m_neutral->minimum())
    options.neutralFrame = m_neutral->value();
  return options;
}

void FaceMeshPanel::applyOptions()
{
  if (m_loadingSettings)
    return;
  m_methodPages->setCurrentIndex(std::max(0, m_method->currentIndex()));
  const bool compare = m_compare->isChecked();
  if (compare != m_model.compare())
    m_model.setCompare(compare);
  m_model.setOptions(optionsFromUi());
  writeSettings();
}

void FaceMeshPanel::onTakeReset()
{
  const Take& take = m_document.take();
  // The neutral frame spin box: its minimum (one before the first frame) reads "auto".
  const QSignalBlocker blocker(m_neutral);
  const auto first = static_cast<int>(take.firstFrame());
  m_neutral->setRange(first - 1, first + static_cast<int>(std::max<Eigen::Index>(take.frameCount(), 1)) - 1);
  m_neutral->setSpecialValueText(tr("first complete"));
  m_neutral->setValue(first - 1);
  m_pendingLabel.clear();
  m_model.setOptions(optionsFromUi());
}

QString FaceMeshPanel::loadMesh(const QString& path)
{
  Mesh mesh;
  try {
    mesh = readMesh(path.toStdString());
  } catch (const std::exception& e) {
    showError(tr("Cannot read the mesh %1: %2").arg(QFileInfo(path).fileName(), QString::fromStdString(e.what())));
    return m_status->text();
  }
  m_model.setMesh(std::move(mesh), path);
  updateRigStatus();
  return {};
}

void FaceMeshPanel::updateMeshLabel()
{
  if (!m_model.hasMesh()) {
    m_meshLabel->setText(tr("No mesh"));
    return;
  }
  const QString name = m_model.meshPath().isEmpty() ? tr("Mesh") : QFileInfo(m_model.meshPath()).fileName();
  m_meshLabel->setText(tr("%1: %n vertices", nullptr, static_cast<int>(m_model.mesh().vertexCount())).arg(name));
}

QString FaceMeshPanel::loadBinding(const QString& path)
{
  if (!m_model.hasMesh()) {
    showError(tr("Load the mesh the binding is for first."));
    return m_status->text();
  }
  MeshBinding binding;
  try {
    binding = readBinding(path.toStdString(), m_model.mesh().vertexCount());
  } catch (const std::exception& e) {
    showError(tr("Cannot read the binding %1: %2").arg(QFileInfo(path).fileName(), QString::fromStdString(e.what())));
    return m_status->text();
  }
  m_model.setBinding(std::move(binding));
  updateRigStatus();
  return m_model.error();
}

QString FaceMeshPanel::saveBinding(const QString& path)
{
  try {
    writeFileAtomically(path.toStdString(), bindingJson(m_model.binding()));
  } catch (const std::exception& e) {
    showError(tr("Cannot save the binding: %1").arg(QString::fromStdString(e.what())));
    return m_status->text();
  }
  m_status->setText(tr("Saved %1").arg(QFileInfo(path).fileName()));
  return {};
}

QString FaceMeshPanel::autoBind()
{
  const Take& take = m_document.take();
  std::vector<std::string> labels;
  if (m_document.selection().size() >= 3) {
    for (const Eigen::Index m : m_document.selection())
      labels.push_back(take.label(m));
  } else if (!take.empty()) {
    const Eigen::Index frame = mostCompleteFrame(take);
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      const std::string& label = take.label(m);
      if (take.isValid(frame, m) && !isUnlabelledLabel(label) && !m_document.isReferenceMarker(m))
        labels.push_back(label);
    }
  }
  const QString error = m_model.autoBindMarkers(labels);
  if (!error.isEmpty()) {
    showError(tr("Auto-bind: %1").arg(error));
    return m_status->text();
  }
  updateRigStatus();
  return m_model.error();
}

void FaceMeshPanel::setPicking(bool on)
{
  m_pick->setChecked(on);
}

bool FaceMeshPanel::picking() const
{
  return m_pick->isChecked();
}

void FaceMeshPanel::onSelectionChanged()
{
  const auto& selection = m_document.selection();
  m_pendingLabel = selection.size() == 1 ? m_document.take().label(selection.front()) : std::string();
  if (picking())
    m_status->setText(m_pendingLabel.empty()
                          ? tr("Select a marker, then click its vertex on the mesh")
                          : tr("Click the vertex for %1").arg(QString::fromStdString(m_pendingLabel)));
}

bool FaceMeshPanel::eventFilter(QObject* watched, QEvent* event)
{
  if (!picking() || (event->type() != QEvent::MouseButtonPress && event->type() != QEvent::MouseButtonRelease))
    return QWidget::eventFilter(watched, event);
  const auto* mouse = static_cast<QMouseEvent*>(event);
  const QPoint position = mouse->position().toPoint();
  if (mouse->button() != Qt::LeftButton || mouse->modifiers() != Qt::NoModifier)
    return false;
  if (event->type() == QEvent::MouseButtonPress) {
    m_pressPosition = position;
    return false;
  }
  // A click (not an orbit drag) binds the pending marker; it never reaches the view's selection.
  if ((position - m_pressPosition).manhattanLength() > kClickSlop)
    return false;
  return pickVertex(position);
}

bool FaceMeshPanel::pickVertex(QPoint position)
{
  const auto marker = m_document.take().markerIndex(m_pendingLabel);
  if (m_pendingLabel.empty() || !marker)
    return false;
  // Markers sit on the skin, so a click on one also hits the mesh: another marker is a new pick.
  const Eigen::Index other = m_view.markerAt(position, kMarkerRadius);
  if (other >= 0 && other != *marker)
    return false;
  const Eigen::Index vertex = m_scene.layer().vertexAt(m_view.viewport()->displayPixel(position));
  if (vertex < 0)
    return false;
  const double before = pickResidual(*marker);
  m_undo->push(new RebindMarkerCommand(m_model, m_pendingLabel,
                                       MarkerBinding{m_pendingLabel, MeshPoint::atVertex(vertex),
                                                     std::numeric_limits<double>::quiet_NaN()}));
  QString text = tr("%1 bound to vertex %2").arg(QString::fromStdString(m_pendingLabel)).arg(vertex);
  const double after = pickResidual(*marker);
  if (std::isfinite(after))
    text += std::isfinite(before) ? tr("; residual %1 mm (was %2 mm)").arg(after, 0, 'f', 2).arg(before, 0, 'f', 2)
                                  : tr("; residual %1 mm").arg(after, 0, 'f', 2);
  m_status->setText(text);
  return true;
}

QString FaceMeshPanel::statusText() const
{
  return m_status->text();
}

double FaceMeshPanel::pickResidual(Eigen::Index marker) const
{
  // The rig's placement puts the neutral frame on the mesh; the residual is how far the placed
  // marker is from its bound point, in take units (the placement's scale divided out).
  const FaceRig* rig = m_model.rig();
  if (!rig)
    return std::numeric_limits<double>::quiet_NaN();
  const auto& labels = rig->labels();
  const auto bound = std::find(labels.begin(), labels.end(), m_document.take().label(marker));
  if (bound == labels.end())
    return std::numeric_limits<double>::quiet_NaN();
  const Take& take = m_model.rigTake();
  const auto i = static_cast<std::size_t>(bound - labels.begin());
  const Eigen::Index frame = rig->neutralFrame(), index = rig->markers()[i];
  if (frame < 0 || frame >= take.frameCount() || !take.valid()(frame, index))
    return std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector3d placed = rig->placement().apply(take.position(frame, index));
  return (placed - rig->points()[i].on(m_model.mesh().vertices)).norm() / rig->placement().scale;
}

QString FaceMeshPanel::timingText() const
{
  if (m_scene.lastDeformMs() < 0.0)
    return {};
  const auto name = [](const FaceRig* rig) {
    return rig && rig->options().method == DeformMethod::Laplacian ? tr("Laplacian") : tr("RBF");
  };
  QString text = tr("Deform per frame: %1 %2 ms")
                     .arg(name(m_model.rig()))
                     .arg(m_scene.lastDeformMs(), 0, 'f', 3);
  if (m_scene.lastCompareMs() >= 0.0)
    text += tr(", %1 %2 ms").arg(name(m_model.compareRig())).arg(m_scene.lastCompareMs(), 0, 'f', 3);
  return text;
}

QString FaceMeshPanel::bindingSummary() const
{
  const MeshBinding& binding = m_model.binding();
  double sum = 0.0;
  int known = 0;
  for (const MarkerBinding& marker : binding.markers)
    if (std::isfinite(marker.residual)) {
      sum += marker.residual;
      ++known;
    }
  QString text = m_model.bindingSummary();
  if (known > 0)
    text += tr("; mean residual %1 mm").arg(sum / known, 0, 'f', 2);
  return text;
}

void FaceMeshPanel::updateBindingSummary()
{
  m_bindingLabel->setText(bindingSummary());
}

void FaceMeshPanel::updateRigStatus()
{
  if (!m_model.error().isEmpty()) {
    showError(m_model.error());
    return;
  }
  m_status->setStyleSheet(QString());
  if (!m_model.hasMesh())
    m_status->clear();  // a new take without the previous one's mesh
  else if (const FaceRig* rig = m_model.rig())
    m_status->setText(tr("Neutral frame %1; set-up %2 ms")
                          .arg(static_cast<qlonglong>(m_document.take().firstFrame() + rig->neutralFrame()))
                          .arg(1e3 * rig->setupSeconds(), 0, 'f', 1));
  m_timing->setText(timingText());
}

void FaceMeshPanel::showError(const QString& message)
{
  showStatusLine(*m_status, message, true);
}

void FaceMeshPanel::loadMeshDialog()
{
  const QString path =
      openFileOfGroup(this, tr("Load face mesh"), kGroup, tr("Meshes (*.obj *.ply *.glb *.gltf);;All files (*)"));
  if (!path.isEmpty())
    (void)loadMesh(path);
}

void FaceMeshPanel::loadBindingDialog()
{
  const QString path = openFileOfGroup(this, tr("Load marker binding"), kGroup, tr("Bindings (*.json);;All files (*)"));
  if (!path.isEmpty())
    (void)loadBinding(path);
}

void FaceMeshPanel::saveBindingDialog()
{
  const QString path = saveFileOfGroup(this, tr("Save marker binding"), kGroup, tr("Bindings (*.json)"));
  if (!path.isEmpty())
    (void)saveBinding(path);
}

} // namespace mocap::ui
