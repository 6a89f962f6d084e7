#include "views/face_mesh_scene.h"

#include "document/take_document.h"
#include "views/marker_view_3d.h"
#include "views/mesh_layer.h"
#include "views/vtk_viewport.h"

#include "mocap/deform/retarget.h"

#include <QElapsedTimer>
#include <QGuiApplication>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

namespace {

constexpr double kCompareGap = 1.15;  // the compared mesh sits this many mesh widths to the side

double elapsedMs(const QElapsedTimer& clock)
{
  return static_cast<double>(clock.nsecsElapsed()) * 1e-6;
}

/// The inverse of x ↦ s·R·x + t.
Eigen::Affine3d inverseOf(const Similarity& similarity)
{
  Eigen::Affine3d inverse = Eigen::Affine3d::Identity();
  inverse.linear() = similarity.rotation.transpose() / similarity.scale;
  inverse.translation() = -(inverse.linear() * similarity.translation);
  return inverse;
}

/// Busy cursor while a rig is set up (milliseconds for a small face, longer for a dense one).
class BusyCursor
{
public:
  BusyCursor() { QGuiApplication::setOverrideCursor(Qt::WaitCursor); }
  ~BusyCursor() { QGuiApplication::restoreOverrideCursor(); }
  BusyCursor(const BusyCursor&) = delete;
  BusyCursor& operator=(const BusyCursor&) = delete;
};

} // namespace

FaceMeshScene::FaceMeshScene(TakeDocument& document, MarkerView3d& view, QObject* parent)
    : QObject(parent), m_document(document), m_view(view),
      m_layer(std::make_unique<MeshLayer>(view.viewport()->renderer())),
      m_compareLayer(std::make_unique<MeshLayer>(view.viewport()->renderer()))
{
  m_compareLayer->setColor(QColor(172, 200, 236));
  connect(&document, &TakeDocument::takeReset, this, [this] {
    restabilize();
    rebuild();
  });
  // An edit may move the neutral frame's markers or the head pose: set the rigs up again.
  connect(&document, &TakeDocument::samplesChanged, this, [this] {
    restabilize();
    rebuild();
  });
  connect(&document, &TakeDocument::markersChanged, this, [this] {
    restabilize();
    rebuild();
  });
  connect(&document, &TakeDocument::currentFrameChanged, this, &FaceMeshScene::updateFrame);
  // The view's head-stabilized frame can change without a document signal (Ctrl+B).
  connect(view.viewport(), &VtkViewport::aboutToRender, this, &FaceMeshScene::updatePlacement);
}

FaceMeshScene::~FaceMeshScene() = default;

const Take& FaceMeshScene::rigTake() const
{
  return m_stabilized ? *m_stabilized : m_document.take();
}

void FaceMeshScene::setMesh(Mesh mesh)
{
  m_mesh = std::move(mesh);
  m_layer->setMesh(m_mesh);
  m_compareLayer->setMesh(m_mesh);
  if (m_binding.meshVertices != m_mesh.vertexCount()) {
    ++m_bindingGeneration;
    m_binding = MeshBinding{};
    m_binding.meshVertices = m_mesh.vertexCount();
    emit bindingChanged();
  }
  emit meshChanged();
  rebuild();
}

void FaceMeshScene::setBinding(MeshBinding binding)
{
  ++m_bindingGeneration;
  m_binding = std::move(binding);
  m_binding.meshVertices = m_mesh.vertexCount();
  emit bindingChanged();
  rebuild();
}

std::optional<MarkerBinding> FaceMeshScene::rebind(const std::string& label, std::optional<MarkerBinding> binding)
{
  auto& markers = m_binding.markers;
  const auto it =
      std::find_if(markers.begin(), markers.end(), [&](const MarkerBinding& m) { return m.label == label; });
  std::optional<MarkerBinding> previous;
  if (it != markers.end()) {
    previous = *it;
    if (binding)
      *it = std::move(*binding);
    else
      markers.erase(it);
  } else if (binding) {
    markers.push_back(std::move(*binding));
  }
  emit bindingChanged();
  rebuild();
  return previous;
}

QString FaceMeshScene::autoBindMarkers(const std::vector<std::string>& labels)
{
  if (!hasMesh())
    return tr("Load a mesh first.");
  if (!m_stabilizationError.isEmpty())
    return m_stabilizationError;
  try {
    const Take& take = rigTake();
    const std::vector<Eigen::Index> markers = markerIndices(take, labels);
    const Eigen::Index neutral = chooseNeutralFrame(take, markers, m_options.neutralFrame);
    MeshBinding binding;
    {
      const BusyCursor busy;
      binding = autoBind(m_mesh, labels, markerPositions(take, neutral, markers));
    }
    setBinding(std::move(binding));
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

void FaceMeshScene::setStabilization(std::vector<std::string> labels)
{
  m_stabilization = std::move(labels);
  restabilize();
  rebuild();
}

void FaceMeshScene::setOptions(const FaceRigOptions& options)
{
  m_options = options;
  rebuild();
}

void FaceMeshScene::setCompare(bool on)
{
  m_compare = on;
  rebuild();
}

void FaceMeshScene::restabilize()
{
  m_stabilized.reset();
  m_headMotion.reset();
  m_stabilizationError.clear();
  m_viewReference.clear();  // the view's head pose is estimated again too (an edit may move it)
  m_viewMotion.reset();
  if (m_stabilization.empty() || !m_document.hasTake())
    return;
  try {
    HeadMotion motion = estimateHeadMotion(m_document.take(), markerIndices(m_document.take(), m_stabilization));
    Take stabilized = m_document.take();
    removeHeadMotion(stabilized, motion);
    m_stabilized = std::move(stabilized);
    m_headMotion = std::move(motion);
  } catch (const std::exception& e) {
    m_stabilizationError = tr("Head stabilization: %1").arg(QString::fromStdString(e.what()));
  }
}

void FaceMeshScene::rebuild()
{
  m_rig.reset();
  m_compareRig.reset();
  m_error.clear();
  if (!m_stabilizationError.isEmpty()) {
    m_error = m_stabilizationError;
  } else if (hasMesh() && m_binding.markers.empty()) {
    m_error = tr("No marker is bound to the mesh: auto-bind, load a binding or pick vertices.");
  } else if (hasMesh() && m_document.hasTake()) {
    try {
      const BusyCursor busy;
      FaceRigOptions primary = m_options;
      if (primary.method == DeformMethod::Rbf)
        primary.rotations = 0;
      m_rig = std::make_unique<FaceRig>(m_mesh, m_binding, rigTake(), primary);
      if (m_compare) {
        FaceRigOptions other = m_options;
        other.method = primary.method == DeformMethod::Rbf ? DeformMethod::Laplacian : DeformMethod::Rbf;
        if (other.method == DeformMethod::Rbf)
          other.rotations = 0;
        m_compareRig = std::make_unique<FaceRig>(m_mesh, m_binding, rigTake(), other);
      }
    } catch (const std::exception& e) {
      m_rig.reset();
      m_compareRig.reset();
      m_error = QString::fromStdString(e.what());
    }
  }
  if (hasMesh()) {
    m_layer->setVertices(m_mesh.vertices);
    m_compareLayer->setVertices(m_mesh.vertices);
  }
  emit rigChanged();
  updateFrame();
}

void FaceMeshScene::updateFrame()
{
  m_deformMs = m_compareMs = -1.0;
  const Take& take = rigTake();
  const Eigen::Index frame = m_document.currentFrame();
  if (m_rig && frame < take.frameCount()) {
    try {
      QElapsedTimer clock;
      clock.start();
      (void)m_rig->deform(take, frame, m_deformed);
      m_deformMs = elapsedMs(clock);
      m_layer->setVertices(m_deformed);
      if (m_compareRig) {
        clock.restart();
        (void)m_compareRig->deform(take, frame, m_deformed);
        m_compareMs = elapsedMs(clock);
        m_compareLayer->setVertices(m_deformed);
      }
    } catch (const std::exception& e) {  // the take changed under the rig; the next rebuild fixes it
      m_error = QString::fromStdString(e.what());
      m_rig.reset();
      m_compareRig.reset();
      emit rigChanged();
    }
  }
  updatePlacement();
  m_view.viewport()->requestRender();
  if (m_deformMs >= 0.0)
    emit deformed(m_deformMs, m_compareMs);
}

void FaceMeshScene::updatePlacement()
{
  if (!hasMesh())
    return;
  if (m_view.headReference() != m_viewReference) {
    m_viewReference = m_view.headReference();
    m_viewMotion.reset();
    if (!m_viewReference.empty()) {
      try {
        m_viewMotion = estimateHeadMotion(m_document.take(), m_viewReference);
      } catch (const std::exception&) {
        m_viewMotion.reset();  // the view refuses such a reference too and stays in the lab frame
      }
    }
  }
  const std::optional<Eigen::Affine3d> placement = meshToScene(m_document.currentFrame());
  m_layer->setVisible(placement.has_value());
  m_compareLayer->setVisible(placement.has_value() && m_compare);
  if (!placement)
    return;
  m_layer->setPlacement(*placement);
  const double width = m_mesh.vertices.col(0).maxCoeff() - m_mesh.vertices.col(0).minCoeff();
  m_compareLayer->setPlacement(*placement * Eigen::Translation3d(kCompareGap * width, 0.0, 0.0));
}

std::optional<Eigen::Affine3d> FaceMeshScene::meshToScene(Eigen::Index frame) const
{
  Eigen::Affine3d toScene;
  if (m_rig)
    toScene = inverseOf(m_rig->placement());
  else if (m_binding.hasAlignment)
    toScene = inverseOf(m_binding.alignment);
  else
    return std::nullopt;
  const auto index = static_cast<std::size_t>(frame);
  if (m_headMotion && index < m_headMotion->poses.size())
    toScene = Eigen::Affine3d(m_headMotion->poses[index]) * toScene;  // back onto the captured head
  if (m_viewMotion && index < m_viewMotion->poses.size())
    toScene = Eigen::Affine3d(m_viewMotion->poses[index].inverse()) * toScene;  // as the view draws markers
  return toScene;
}

Eigen::Index FaceMeshScene::vertexAt(QPoint position) const
{
  return m_layer->vertexAt(m_view.viewport()->displayPixel(position));
}

QPointF FaceMeshScene::vertexPosition(Eigen::Index vertex) const
{
  return m_view.viewport()->widgetPosition(m_layer->scenePosition(vertex));
}

} // namespace mocap::ui
