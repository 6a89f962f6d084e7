#include "views/blendshape_scene.h"

#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/take_document.h"
#include "document/view_state.h"
#include "views/face_mesh_scene.h"
#include "views/mesh_layer.h"

namespace mocap::ui {

BlendshapeScene::BlendshapeScene(BlendshapeSolveModel& model, FaceMeshModel& faceMesh, vtkRenderer* renderer,
                                 const DrawnPositions& markers, QObject* parent)
    : QObject(parent), m_model(model), m_faceMesh(faceMesh), m_markers(markers),
      m_layer(std::make_unique<MeshLayer>(renderer))
{
  m_layer->setColor(QColor(236, 196, 160));  // warm, apart from the deformed mesh's colours
  m_layer->setVisible(false);
  connect(&model, &BlendshapeSolveModel::rigChanged, this, &BlendshapeScene::updateMesh);
  connect(&model, &BlendshapeSolveModel::resultChanged, this, &BlendshapeScene::updateFrame);
  connect(&model, &BlendshapeSolveModel::weightsEdited, this, &BlendshapeScene::updateFrame);
  connect(&faceMesh, &FaceMeshModel::rigChanged, this, &BlendshapeScene::updateFrame);
  connect(&faceMesh.document(), &TakeDocument::currentFrameChanged, this, &BlendshapeScene::updateFrame);
}

BlendshapeScene::~BlendshapeScene() = default;

void BlendshapeScene::observe(const ViewState& state)
{
  setShown(state.rigShown());
  setBeside(state.rigBeside());
  connect(&state, &ViewState::rigShownChanged, this, &BlendshapeScene::setShown);
  connect(&state, &ViewState::rigBesideChanged, this, &BlendshapeScene::setBeside);
}

void BlendshapeScene::setShown(bool shown)
{
  m_shown = shown;
  updateFrame();
}

void BlendshapeScene::setBeside(bool beside)
{
  m_beside = beside;
  updatePlacement();
  emit changed();
}

void BlendshapeScene::updateMesh()
{
  if (m_model.hasRig())
    m_layer->setMesh(m_model.rig()->neutral);
  else
    m_layer->clear();
  updateFrame();
}

void BlendshapeScene::updateFrame()
{
  const bool posed = m_shown && m_layer->hasMesh() &&
                     m_model.pose(m_faceMesh.document().currentFrame(), m_posed) &&
                     m_posed.rows() == m_layer->vertices().rows();
  if (posed)
    m_layer->setVertices(m_posed);
  m_posedShown = posed;
  updatePlacement();
  emit changed();
}

void BlendshapeScene::updatePlacement()
{
  const std::optional<Eigen::Affine3d> placement = meshPlacement(m_faceMesh, m_markers);
  m_layer->setVisible(m_posedShown && placement.has_value());
  if (!m_posedShown || !placement)
    return;
  const double offset = m_beside ? -sideOffset(m_model.rig()->neutral) : 0.0;
  m_layer->setPlacement(*placement * Eigen::Translation3d(offset, 0.0, 0.0));
}

} // namespace mocap::ui
