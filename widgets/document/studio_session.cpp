#include "document/studio_session.h"

#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/layout_plan_model.h"
#include "document/live_stream.h"
#include "document/reference_videos.h"
#include "document/studio_options.h"
#include "document/take_document.h"
#include "document/view_state.h"

#include "mocap/deform/mesh_binding.h"
#include "mocap/io/mesh_io.h"

#include <QUndoStack>

#include <string>
#include <vector>

namespace mocap::ui {

/// What an actor's rig is made of, kept across takes.
struct StudioSession::KeptRig
{
  Mesh mesh;
  QString meshPath;
  MeshBinding binding;
  std::shared_ptr<const BlendshapeRig> rig;
  QString rigPath;
};

StudioSession::StudioSession(QObject* parent)
    : QObject(parent), m_document(new TakeDocument(this)), m_view(new ViewState(this)),
      m_options(std::make_unique<StudioOptions>())
{
  // Connected before the models exist: the previous take's context is gone before they or any
  // view handle the new take.
  connect(m_document, &TakeDocument::takeReset, this, &StudioSession::dropPreviousTake);
  m_faceMesh = new FaceMeshModel(*m_document, this);
  m_blendshapes = new BlendshapeSolveModel(this);
  m_videos = new ReferenceVideos(*m_document, this);
  m_layoutPlan = new LayoutPlanModel(*m_document, this);
  m_liveStream = new LiveStream(*this, this);
  // After the models have the new take, before any view: the face follows the take's head
  // markers, then a kept rig is bound to the new take (so Reset Camera frames it).
  connect(m_document, &TakeDocument::takeReset, this, &StudioSession::followReferenceMarkers);
  connect(m_document, &TakeDocument::referenceMarkersChanged, this, &StudioSession::followReferenceMarkers);
  connect(m_document, &TakeDocument::takeReset, this, &StudioSession::restoreKeptRig);
}

StudioSession::~StudioSession() = default;

void StudioSession::followOptions()
{
  m_view->followOptions(*m_options);
  m_options->keepRig.follow(this, [this](bool keep) { setKeepRig(keep); });
  m_options->showModelOutputs.follow(this, [this](bool show) { m_document->setShowModelOutputs(show); });
}

QUndoStack* StudioSession::undoStack() const
{
  return m_document->undoStack();
}

BoundRig StudioSession::boundRig() const
{
  const auto& rig = m_blendshapes->rig();
  if (!rig || m_faceMesh->mesh().vertexCount() != rig->neutral.vertexCount())
    return {};
  return {rig, m_faceMesh->binding()};
}

namespace {
const QString kMeshKey = QStringLiteral("mesh");
const QString kBindingKey = QStringLiteral("binding");
} // namespace

QVariantMap StudioSession::recoveryState() const
{
  QVariantMap state;
  if (m_faceMesh->hasMesh()) {
    state.insert(kMeshKey, m_faceMesh->meshPath());
    state.insert(kBindingKey, QString::fromStdString(bindingJson(m_faceMesh->binding())));
  }
  return state;
}

QString StudioSession::restoreRecoveryState(const QVariantMap& state)
{
  const QString meshPath = state.value(kMeshKey).toString();
  if (meshPath.isEmpty())
    return {};
  try {
    Mesh mesh = readMesh(meshPath.toStdString());
    const Eigen::Index vertices = mesh.vertexCount();
    m_faceMesh->setMesh(std::move(mesh), meshPath);
    m_faceMesh->setBinding(parseBinding(state.value(kBindingKey).toString().toStdString(), "recovered binding", vertices));
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  return m_faceMesh->error();
}

void StudioSession::dropPreviousTake()
{
  m_kept.reset();
  if (m_keepRig && (m_faceMesh->hasMesh() || m_blendshapes->hasRig()))
    m_kept.reset(new KeptRig{m_faceMesh->mesh(), m_faceMesh->meshPath(), m_faceMesh->bindingToKeep(),
                             m_blendshapes->rig(), m_blendshapes->rigPath()});
  // Still the previous take's, they would be drawn on this one.
  if (m_faceMesh->hasMesh())
    m_faceMesh->clear();
  m_faceMesh->setStabilization({});  // the previous take's head markers mean nothing here
  if (m_blendshapes->hasRig() || m_blendshapes->hasResult())
    m_blendshapes->setRig(nullptr, {});
}

void StudioSession::followReferenceMarkers()
{
  std::vector<std::string> labels = m_document->referenceLabels();
  if (labels != m_faceMesh->stabilization())
    m_faceMesh->setStabilization(std::move(labels));
}

void StudioSession::restoreKeptRig()
{
  const std::unique_ptr<KeptRig> kept = std::move(m_kept);
  if (kept) {
    if (kept->mesh.vertexCount() > 0) {
      m_faceMesh->setMesh(std::move(kept->mesh), kept->meshPath);
      m_faceMesh->bindKeptRig(std::move(kept->binding));
    }
    if (kept->rig)
      m_blendshapes->setRig(std::move(kept->rig), kept->rigPath);
  }
  emit takeContextReset(kept != nullptr);
}

} // namespace mocap::ui
