#include "views/face_mesh_scene.h"

#include "document/face_mesh_model.h"
#include "document/take_document.h"
#include "document/view_state.h"
#include "views/drawn_positions.h"
#include "views/mesh_layer.h"

#include <QElapsedTimer>

namespace mocap::ui {

namespace {

double elapsedMs(const QElapsedTimer& clock)
{
  return static_cast<double>(clock.nsecsElapsed()) * 1e-6;
}

} // namespace

double sideOffset(const Mesh& mesh)
{
  constexpr double kGap = 1.15;  // a mesh beside another sits this many mesh widths to the side
  if (mesh.vertexCount() == 0)
    return 0.0;
  return kGap * (mesh.vertices.col(0).maxCoeff() - mesh.vertices.col(0).minCoeff());
}

std::optional<Eigen::Affine3d> meshPlacement(const FaceMeshModel& model, const DrawnPositions& markers)
{
  if (!model.hasMesh())
    return std::nullopt;
  // The markers are drawn in the head frame of their reference markers: so is the mesh placed.
  std::shared_ptr<const HeadMotion> viewMotion;
  if (!markers.headReference().empty()) {
    try {
      viewMotion = model.document().headMotion(markers.headReference());
    } catch (const std::exception&) {
      viewMotion.reset();  // the view refuses such a reference too and stays in the lab frame
    }
  }
  const Eigen::Index frame = model.document().currentFrame();
  std::optional<Eigen::Affine3d> placement = model.meshToLab(frame);
  const auto index = static_cast<std::size_t>(frame);
  if (placement && viewMotion && index < viewMotion->poses.size())
    placement = Eigen::Affine3d(viewMotion->poses[index].inverse()) * *placement;  // as the view draws markers
  return placement;
}

void FaceMeshScene::observe(const ViewState& state)
{
  auto applyLook = [this, &state] {
    for (MeshLayer* layer : {m_layer.get(), m_compareLayer.get()}) {
      layer->setOpacity(state.meshOpacity());
      layer->setEdgesVisible(state.meshEdges());
    }
    emit changed();
  };
  applyLook();
  connect(&state, &ViewState::meshLookChanged, this, applyLook);
}

FaceMeshScene::FaceMeshScene(FaceMeshModel& model, vtkRenderer* renderer, const DrawnPositions& markers,
                             QObject* parent)
    : QObject(parent), m_model(model), m_markers(markers), m_layer(std::make_unique<MeshLayer>(renderer)),
      m_compareLayer(std::make_unique<MeshLayer>(renderer))
{
  m_compareLayer->setColor(QColor(172, 200, 236));
  connect(&model, &FaceMeshModel::meshChanged, this, [this] {
    for (MeshLayer* layer : {m_layer.get(), m_compareLayer.get()}) {
      if (m_model.hasMesh())
        layer->setMesh(m_model.mesh());
      else
        layer->clear();  // nothing left drawn (or framed by Reset Camera)
    }
    emit changed();
  });
  connect(&model, &FaceMeshModel::rigChanged, this, [this] {
    showRestPose();
    updateFrame();
  });
  TakeDocument& document = model.document();
  connect(&document, &TakeDocument::currentFrameChanged, this, &FaceMeshScene::updateFrame);
}

FaceMeshScene::~FaceMeshScene() = default;

void FaceMeshScene::showRestPose()
{
  if (!m_model.hasMesh())
    return;
  m_layer->setVertices(m_model.mesh().vertices);
  m_compareLayer->setVertices(m_model.mesh().vertices);
}

void FaceMeshScene::updateFrame()
{
  m_deformMs = m_compareMs = -1.0;
  const Eigen::Index frame = m_model.document().currentFrame();
  QElapsedTimer clock;
  clock.start();
  if (m_model.deform(frame, m_deformed)) {
    m_deformMs = elapsedMs(clock);
    m_layer->setVertices(m_deformed);
    clock.restart();
    if (m_model.compareRig() && m_model.deform(frame, m_deformed, true)) {
      m_compareMs = elapsedMs(clock);
      m_compareLayer->setVertices(m_deformed);
    }
  }
  updatePlacement();
  emit changed();
  if (m_deformMs >= 0.0)
    emit deformed(m_deformMs, m_compareMs);
}

void FaceMeshScene::updatePlacement()
{
  if (!m_model.hasMesh())
    return;
  const std::optional<Eigen::Affine3d> placement = this->placement();
  m_layer->setVisible(placement.has_value());
  m_compareLayer->setVisible(placement.has_value() && m_model.compare());
  if (!placement)
    return;
  m_layer->setPlacement(*placement);
  m_compareLayer->setPlacement(*placement * Eigen::Translation3d(sideOffset(m_model.mesh()), 0.0, 0.0));
}

} // namespace mocap::ui
