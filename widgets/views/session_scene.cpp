#include "views/session_scene.h"

#include "document/studio_session.h"
#include "views/blendshape_scene.h"
#include "views/face_mesh_scene.h"
#include "views/marker_scene.h"

namespace mocap::ui {

SessionScene::SessionScene(StudioSession& session, const MarkerScene& markers, QObject* parent)
    : QObject(parent),
      m_faceMesh(std::make_unique<FaceMeshScene>(session.faceMesh(), markers.renderer(), markers.positions())),
      m_blendshapes(std::make_unique<BlendshapeScene>(session.blendshapes(), session.faceMesh(), markers.renderer(),
                                                      markers.positions()))
{
  connect(m_faceMesh.get(), &FaceMeshScene::changed, this, &SessionScene::changed);
  connect(m_blendshapes.get(), &BlendshapeScene::changed, this, &SessionScene::changed);
}

SessionScene::~SessionScene() = default;

void SessionScene::observe(const ViewState& state)
{
  m_faceMesh->observe(state);
  m_blendshapes->observe(state);
}

void SessionScene::beforeRender()
{
  m_faceMesh->updatePlacement();
  m_blendshapes->updatePlacement();
}

} // namespace mocap::ui
