#include "views/scene_settings.h"

#include "document/view_state.h"
#include "views/marker_scene.h"
#include "views/marker_view_3d.h"
#include "views/vtk_viewport.h"

#include <vtkCamera.h>
#include <vtkMath.h>
#include <vtkRenderer.h>

#include <cmath>

namespace mocap::ui {

CameraState cameraState(vtkCamera& camera, QSize viewSize)
{
  CameraState state;
  camera.GetPosition(state.position.data());
  camera.GetFocalPoint(state.focalPoint.data());
  camera.GetViewUp(state.viewUp.data());
  state.viewAngle = camera.GetViewAngle();
  state.viewSize = viewSize;
  return state;
}

void applyCameraState(const CameraState& state, vtkCamera& camera, QSize viewSize)
{
  camera.SetPosition(state.position.data());
  camera.SetFocalPoint(state.focalPoint.data());
  camera.SetViewUp(state.viewUp.data());
  camera.SetViewAngle(state.viewAngle);
  if (state.viewSize.isEmpty() || viewSize.isEmpty())
    return;
  const double stateAspect = static_cast<double>(state.viewSize.width()) / state.viewSize.height();
  const double aspect = static_cast<double>(viewSize.width()) / viewSize.height();
  if (aspect >= stateAspect)
    return;
  const double halfAngle = vtkMath::RadiansFromDegrees(state.viewAngle / 2.0);
  camera.SetViewAngle(2.0 * vtkMath::DegreesFromRadians(std::atan(std::tan(halfAngle) * stateAspect / aspect)));
}

SceneSettings viewSettings(const MarkerView3d& view)
{
  SceneSettings settings;
  settings.upAxis = view.upAxis();
  settings.trailFrames = view.trailFrames();
  settings.markerScale = view.markerScale();
  settings.linksVisible = view.linksVisible();
  settings.headReference = view.headReference();
  settings.followHead = view.followHead();
  settings.layoutKept = view.layoutHighlight();
  settings.layoutReference = view.layoutReference();
  settings.camera = cameraState(*view.viewport()->renderer()->GetActiveCamera(), view.viewport()->size());
  return settings;
}

SceneSettings shownSettings(const MarkerView3d& view, const ViewState& state)
{
  SceneSettings settings = viewSettings(view);
  settings.meshOpacity = state.meshOpacity();
  settings.meshEdges = state.meshEdges();
  settings.rigShown = state.rigShown();
  settings.rigBeside = state.rigBeside();
  return settings;
}

void applyViewSettings(const SceneSettings& settings, MarkerScene& markers, QSize viewSize)
{
  markers.setUpAxis(settings.upAxis);
  markers.setTrailFrames(settings.trailFrames);
  markers.setMarkerScale(settings.markerScale);
  markers.setLinksVisible(settings.linksVisible);
  if (!settings.headReference.empty())
    (void)markers.positions().setHeadReference(settings.headReference);
  markers.follow().setOn(settings.followHead);
  if (!settings.layoutKept.empty())
    markers.setLayoutHighlight(settings.layoutKept, settings.layoutReference);
  markers.sizeToTake();
  markers.update();
  if (!settings.camera)
    return;
  vtkRenderer* renderer = markers.renderer();
  applyCameraState(*settings.camera, *renderer->GetActiveCamera(), viewSize);
  renderer->ResetCameraClippingRange();
}

} // namespace mocap::ui
