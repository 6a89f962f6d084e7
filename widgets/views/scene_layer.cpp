#include "views/scene_layer.h"

#include <vtkActor.h>
#include <vtkRenderer.h>

namespace mocap::ui {

SceneLayer::SceneLayer(vtkRenderer* renderer, const TakeDocument& document, const DrawnPositions& positions)
    : m_document(document), m_positions(positions), m_renderer(renderer)
{
  m_renderer->AddActor(m_actor);
}

SceneLayer::~SceneLayer()
{
  m_renderer->RemoveActor(m_actor);
}

} // namespace mocap::ui
