#pragma once

#include <vtkNew.h>
#include <vtkSmartPointer.h>

class vtkActor;
class vtkRenderer;

namespace mocap::ui {

class DrawnPositions;
class TakeDocument;

/// What the marker scene's one-actor layers (MarkerLayer, TrailLayer, LinkLayer) share: the
/// document they draw, where its markers are drawn, and their actor in a VTK renderer, added on
/// construction (so layers made one after the other are drawn in that order) and removed on
/// destruction. The renderer is held, so a layer and the view may go in either order.
class SceneLayer
{
public:
  SceneLayer(const SceneLayer&) = delete;
  SceneLayer& operator=(const SceneLayer&) = delete;

  [[nodiscard]] vtkActor* actor() const { return m_actor.Get(); }

protected:
  SceneLayer(vtkRenderer* renderer, const TakeDocument& document, const DrawnPositions& positions);
  ~SceneLayer();

  const TakeDocument& m_document;
  const DrawnPositions& m_positions;
  vtkNew<vtkActor> m_actor;

private:
  vtkSmartPointer<vtkRenderer> m_renderer;
};

} // namespace mocap::ui
