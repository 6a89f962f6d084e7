#include "document/studio_session.h"

#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/layout_plan_model.h"
#include "document/live_stream.h"
#include "document/reference_video.h"
#include "document/reference_videos.h"
#include "document/retarget_map_model.h"
#include "document/session_state.h"
#include "document/studio_options.h"
#include "document/take_document.h"
#include "document/view_state.h"

#include "mocap/deform/actor_profile.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/io/mesh_io.h"
#include "mocap/io/rig_io.h"
#include "mocap/model/retarget_map.h"

#include <QFileInfo>
#include <QStringList>
#include <QUndoStack>

#include <exception>

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
  QString rigShapeFolder;
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

void StudioSession::setBlendshapeRig(std::shared_ptr<const BlendshapeRig> rig, const QString& path,
                                     const QString& shapeFolder)
{
  if (rig && m_faceMesh->mesh().vertexCount() != rig->neutral.vertexCount())
    m_faceMesh->setMesh(rig->neutral, path);
  m_blendshapes->setRig(std::move(rig), path, shapeFolder);
}

SessionState StudioSession::saveState() const
{
  SessionState state;
  if (m_faceMesh->hasMesh()) {
    state.meshPath = m_faceMesh->meshPath();
    state.binding = bindingJson(m_faceMesh->binding());
  }
  state.rigPath = m_blendshapes->rigPath();
  state.rigShapeFolder = m_blendshapes->rigShapeFolder();
  if (m_blendshapes->hasResult()) {
    state.curves = m_blendshapes->result();
    state.solvedWith = m_blendshapes->solvedWith();
    state.readCurves = m_blendshapes->readCurves();
  }
  state.selectedShapes = m_blendshapes->selectedShapes();
  for (int i = 0; i < m_videos->count(); ++i)
    state.videos.push_back({m_videos->at(i).path(), m_videos->at(i).offset()});
  state.currentVideo = m_videos->currentIndex();
  state.layoutPlan = m_layoutPlan->sharedResult();
  state.layoutSize = m_layoutPlan->selectedSize();
  state.actor = m_blendshapes->actor();
  state.actorPath = m_blendshapes->actorPath();
  const RetargetMapModel& map = m_blendshapes->retargetMap();
  state.retargetMap = map.map();
  state.retargetMapName = map.name();
  state.retargetMapEdited = map.edited();
  return state;
}

namespace {

/// Runs `step`; what it throws goes to `problems` after `what`.
template <class Step>
void restoreStep(QStringList& problems, const QString& what, const Step& step)
{
  try {
    step();
  } catch (const std::exception& e) {
    problems << QStringLiteral("%1: %2").arg(what, QString::fromStdString(e.what()));
  }
}

} // namespace

QString StudioSession::restoreState(const SessionState& state)
{
  QStringList problems;
  // A rig's neutral is its face mesh: read once, with the rig.
  if (!state.meshPath.isEmpty() && state.meshPath != state.rigPath)
    restoreStep(problems, QFileInfo(state.meshPath).fileName(),
                [&] { m_faceMesh->setMesh(readMesh(state.meshPath.toStdString()), state.meshPath); });
  if (!state.rigPath.isEmpty())
    restoreStep(problems, QFileInfo(state.rigPath).fileName(), [&] {
      setBlendshapeRig(std::make_shared<const BlendshapeRig>(
                           readRig(state.rigPath.toStdString(), state.rigShapeFolder.toStdString())),
                       state.rigPath, state.rigShapeFolder);
    });
  if (!state.binding.empty() && m_faceMesh->hasMesh()) {
    restoreStep(problems, tr("the binding"), [&] {
      m_faceMesh->setBinding(parseBinding(state.binding, "recovered binding", m_faceMesh->mesh().vertexCount()));
    });
    if (!m_faceMesh->error().isEmpty())
      problems << tr("the binding: %1").arg(m_faceMesh->error());
  }
  restoreCurves(state, problems);
  if (m_blendshapes->hasRig()) {
    std::vector<Eigen::Index> shapes;
    for (const Eigen::Index shape : state.selectedShapes)
      if (shape >= 0 && shape < m_blendshapes->rig()->shapeCount())
        shapes.push_back(shape);
    m_blendshapes->setSelectedShapes(std::move(shapes));
  }
  restoreVideos(state, problems);
  if (state.layoutPlan)
    m_layoutPlan->setResult(state.layoutPlan, state.layoutSize);
  restoreActorAndMap(state, problems);
  return problems.join(QLatin1Char('\n'));
}

void StudioSession::restoreActorAndMap(const SessionState& state, QStringList& problems)
{
  // None kept (a state of version 1, or no actor then) leaves the actor the take remembers.
  if (state.actor)
    restoreStep(problems, tr("the actor"), [&] {
      if (m_blendshapes->hasRig())
        (void)actorExtents(*state.actor, m_blendshapes->rig()->shapeNames());  // as Load Actor checks it
      m_blendshapes->setActor(state.actor, state.actorPath);
    });
  if (state.retargetMap)
    restoreStep(problems, tr("the retarget map"), [&] {
      checkRetargetMap(*state.retargetMap);
      m_blendshapes->retargetMap().setMap(state.retargetMap, state.retargetMapName, state.retargetMapEdited);
    });
}

void StudioSession::restoreCurves(const SessionState& state, QStringList& problems)
{
  if (state.curves.weights.rows() == 0)
    return;
  const Eigen::Index frames = m_document->take().frameCount();
  if (!m_blendshapes->hasRig() || state.curves.weights.cols() != m_blendshapes->rig()->shapeCount()) {
    problems << tr("the weight curves: they were made for a rig that is not loaded");
    return;
  }
  if (!state.readCurves && state.curves.weights.rows() != frames) {
    problems << tr("the weight curves: %1 frames solved, the take has %2")
                    .arg(static_cast<qlonglong>(state.curves.weights.rows()))
                    .arg(static_cast<qlonglong>(frames));
    return;
  }
  if (state.readCurves) {  // a recording's curves, kept with where they were read from
    BlendshapeSolveResult curves = state.curves;
    std::optional<ReadWeightCurves> read = state.readCurves;
    m_blendshapes->swapCurves(curves, read);
  } else {
    (void)m_blendshapes->setResult(state.curves, state.solvedWith);
  }
}

void StudioSession::restoreVideos(const SessionState& state, QStringList& problems)
{
  // The take's sidecar may have linked them already: opening a linked video only makes it current.
  for (const SessionVideo& video : state.videos) {
    const QString error = m_videos->open(video.path);
    if (!error.isEmpty())
      problems << QStringLiteral("%1: %2").arg(QFileInfo(video.path).fileName(), error);
    else
      m_videos->current()->setOffset(video.offset);
  }
  if (state.currentVideo < 0 || state.currentVideo >= static_cast<int>(state.videos.size()))
    return;
  const QString& current = state.videos[static_cast<std::size_t>(state.currentVideo)].path;
  for (int i = 0; i < m_videos->count(); ++i)
    if (m_videos->at(i).path() == current)
      m_videos->setCurrentIndex(i);
}

void StudioSession::dropPreviousTake()
{
  m_kept.reset();
  if (m_keepRig && (m_faceMesh->hasMesh() || m_blendshapes->hasRig()))
    m_kept.reset(new KeptRig{m_faceMesh->mesh(), m_faceMesh->meshPath(), m_faceMesh->bindingToKeep(),
                             m_blendshapes->rig(), m_blendshapes->rigPath(), m_blendshapes->rigShapeFolder()});
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
      m_blendshapes->setRig(std::move(kept->rig), kept->rigPath, kept->rigShapeFolder);
  }
  emit takeContextReset(kept != nullptr);
}

} // namespace mocap::ui
