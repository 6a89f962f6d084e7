#include "document/face_mesh_model.h"

#include "document/take_document.h"

#include "mocap/deform/retarget.h"

#include <QCursor>
#include <QFileInfo>
#include <QGuiApplication>

#include <algorithm>

namespace mocap::ui {

namespace {

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

FaceMeshModel::FaceMeshModel(TakeDocument& document, QObject* parent) : QObject(parent), m_document(document)
{
  // An edit may move the neutral frame's markers or the head pose: set the rigs up again.
  const auto setUpAgain = [this] {
    restabilize();
    rebuild();
  };
  connect(&document, &TakeDocument::takeReset, this, setUpAgain);
  connect(&document, &TakeDocument::samplesChanged, this, setUpAgain);
  connect(&document, &TakeDocument::markersChanged, this, setUpAgain);
}

FaceMeshModel::~FaceMeshModel() = default;

const Take& FaceMeshModel::rigTake() const
{
  return m_stabilized ? *m_stabilized : m_document.take();
}

std::function<void(Eigen::Index, MeshVertices&)> FaceMeshModel::detachedDeformer() const
{
  auto take = std::make_shared<const Take>(rigTake());
  auto rig = std::make_shared<FaceRig>(m_mesh, m_binding, *take, m_options);
  return [take, rig](Eigen::Index frame, MeshVertices& vertices) { (void)rig->deform(*take, frame, vertices); };
}

void FaceMeshModel::setMesh(Mesh mesh, const QString& path)
{
  m_mesh = std::move(mesh);
  m_meshPath = path.isEmpty() ? QString() : QFileInfo(path).absoluteFilePath();
  m_keptRig = MeshBinding{};
  if (m_binding.meshVertices != m_mesh.vertexCount()) {
    ++m_bindingGeneration;
    m_binding = MeshBinding{};
    m_binding.meshVertices = m_mesh.vertexCount();
    emit bindingChanged();
  }
  emit meshChanged();
  rebuild();
}

void FaceMeshModel::clear()
{
  m_mesh = Mesh{};
  m_meshPath.clear();
  m_keptRig = MeshBinding{};
  ++m_bindingGeneration;
  m_binding = MeshBinding{};
  emit bindingChanged();
  emit meshChanged();
  rebuild();
}

void FaceMeshModel::setBinding(MeshBinding binding)
{
  m_keptRig = MeshBinding{};
  ++m_bindingGeneration;
  m_binding = std::move(binding);
  m_binding.meshVertices = m_mesh.vertexCount();
  emit bindingChanged();
  rebuild();
}

void FaceMeshModel::bindKeptRig(MeshBinding rig)
{
  const Take& take = m_document.take();
  MeshBinding found;
  found.meshVertices = rig.meshVertices;
  for (const MarkerBinding& marker : rig.markers)
    if (take.markerIndex(marker.label))
      found.markers.push_back(marker);
  setBinding(std::move(found));
  m_keptRig = std::move(rig);
  emit bindingChanged();  // the summary counts the kept rig's markers too
}

QString FaceMeshModel::bindingSummary() const
{
  const auto bound = static_cast<int>(m_binding.markers.size());
  if (m_keptRig.markers.empty())
    return tr("%n marker(s) bound", nullptr, bound);
  return tr("%1 of %n rig marker(s) found in this take", nullptr, static_cast<int>(m_keptRig.markers.size())).arg(bound);
}

MeshBinding FaceMeshModel::bindingToKeep() const
{
  MeshBinding kept = m_binding;
  kept.hasAlignment = false;  // made in this take's frame; a rig set up on the next one places the mesh
  // By label, not by the take: when this is asked the document may already hold the next take.
  for (const MarkerBinding& marker : m_keptRig.markers)
    if (std::none_of(m_binding.markers.begin(), m_binding.markers.end(),
                     [&](const MarkerBinding& bound) { return bound.label == marker.label; }))
      kept.markers.push_back(marker);
  return kept;
}

std::optional<MarkerBinding> FaceMeshModel::rebind(const std::string& label, std::optional<MarkerBinding> binding)
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

QString FaceMeshModel::autoBindMarkers(const std::vector<std::string>& labels)
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

void FaceMeshModel::setStabilization(std::vector<std::string> labels)
{
  m_stabilization = std::move(labels);
  restabilize();
  rebuild();
}

void FaceMeshModel::setOptions(const FaceRigOptions& options)
{
  m_options = options;
  rebuild();
}

void FaceMeshModel::setCompare(bool on)
{
  m_compare = on;
  rebuild();
}

void FaceMeshModel::restabilize()
{
  m_stabilized.reset();
  m_headMotion.reset();
  m_stabilizationError.clear();
  if (m_stabilization.empty() || !m_document.hasTake())
    return;
  try {
    std::shared_ptr<const HeadMotion> motion =
        m_document.headMotion(markerIndices(m_document.take(), m_stabilization));
    Take stabilized = m_document.take();
    removeHeadMotion(stabilized, *motion);
    m_stabilized = std::move(stabilized);
    m_headMotion = std::move(motion);
  } catch (const std::exception& e) {
    m_stabilizationError = tr("Head stabilization: %1").arg(QString::fromStdString(e.what()));
  }
}

void FaceMeshModel::rebuild()
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
  emit rigChanged();
}

bool FaceMeshModel::deform(Eigen::Index frame, MeshVertices& vertices, bool compared)
{
  FaceRig* rig = compared ? m_compareRig.get() : m_rig.get();
  const Take& take = rigTake();
  if (!rig || frame < 0 || frame >= take.frameCount())
    return false;
  try {
    (void)rig->deform(take, frame, vertices);
    return true;
  } catch (const std::exception& e) {  // the take changed under the rig; the next rebuild fixes it
    m_error = QString::fromStdString(e.what());
    m_rig.reset();
    m_compareRig.reset();
    emit rigChanged();
    return false;
  }
}

std::optional<Eigen::Affine3d> FaceMeshModel::meshToLab(Eigen::Index frame) const
{
  Eigen::Affine3d toLab;
  if (m_rig)
    toLab = inverseOf(m_rig->placement());
  else if (m_binding.hasAlignment)
    toLab = inverseOf(m_binding.alignment);
  else
    return std::nullopt;
  const auto index = static_cast<std::size_t>(frame);
  if (m_headMotion && index < m_headMotion->poses.size())
    toLab = Eigen::Affine3d(m_headMotion->poses[index]) * toLab;  // back onto the captured head
  return toLab;
}

} // namespace mocap::ui
