#include "views/axes_corner.h"

#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

namespace mocap::ui {

AxesCorner::AxesCorner(vtkRenderWindow& window)
{
  m_renderer->SetViewport(0.0, 0.0, 0.16, 0.2);
  m_renderer->InteractiveOff();
  m_renderer->SetLayer(1);
  m_renderer->AddActor(m_axes);
  window.SetNumberOfLayers(2);
  window.AddRenderer(m_renderer);
}

AxesCorner::~AxesCorner() = default;

void AxesCorner::follow(vtkCamera& scene)
{
  vtkCamera* corner = m_renderer->GetActiveCamera();
  double direction[3];
  scene.GetDirectionOfProjection(direction);
  corner->SetFocalPoint(0, 0, 0);
  corner->SetPosition(-direction[0] * 5.0, -direction[1] * 5.0, -direction[2] * 5.0);
  corner->SetViewUp(scene.GetViewUp());
  m_renderer->ResetCameraClippingRange();
}

} // namespace mocap::ui
