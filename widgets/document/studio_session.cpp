#include "document/studio_session.h"

#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/take_document.h"

#include <QUndoStack>

#include <optional>

namespace mocap::ui {

namespace {

/// What an actor's rig is made of, kept across takes.
struct KeptRig
{
  Mesh mesh;
  QString meshPath;
  MeshBinding binding;
  std::shared_ptr<const BlendshapeRig> rig;
  QString rigPath;
};

} // namespace

StudioSession::StudioSession(QObject* parent) : QObject(parent), m_document(new TakeDocument(this))
{
  // Connected before the models exist, so the new take's context is in place before they and
  // every view handle the new take.
  connect(m_document, &TakeDocument::takeReset, this, &StudioSession::startTakeContext);
  m_faceMesh = new FaceMeshModel(*m_document, this);
  m_blendshapes = new BlendshapeSolveModel(this);
}

StudioSession::~StudioSession() = default;

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

void StudioSession::startTakeContext()
{
  std::optional<KeptRig> kept;
  if (m_keepRig && (m_faceMesh->hasMesh() || m_blendshapes->hasRig()))
    kept = KeptRig{m_faceMesh->mesh(), m_faceMesh->meshPath(), m_faceMesh->bindingToKeep(), m_blendshapes->rig(),
                   m_blendshapes->rigPath()};
  // Still the previous take's, it would be drawn on this one; dropped before anything sets up a rig.
  if (m_faceMesh->hasMesh())
    m_faceMesh->clear();
  if (m_blendshapes->hasRig() || m_blendshapes->hasResult())
    m_blendshapes->setRig(nullptr, {});
  if (kept) {
    if (kept->mesh.vertexCount() > 0) {
      m_faceMesh->setMesh(std::move(kept->mesh), kept->meshPath);
      m_faceMesh->bindKeptRig(std::move(kept->binding));
    }
    if (kept->rig)
      m_blendshapes->setRig(std::move(kept->rig), kept->rigPath);
  }
  emit takeContextReset(kept.has_value());
}

} // namespace mocap::ui
