#pragma once

#include <vtkNew.h>

class vtkAxesActor;
class vtkCamera;
class vtkRenderWindow;
class vtkRenderer;

namespace mocap::ui {

/// The lab axes in the bottom-left corner of a VTK render window (the 3D view's), drawn by a small
/// renderer of its own on a layer above the scene and turned as the scene's camera is.
class AxesCorner
{
public:
  /// Adds the corner renderer to `window`.
  explicit AxesCorner(vtkRenderWindow& window);
  ~AxesCorner();
  AxesCorner(const AxesCorner&) = delete;
  AxesCorner& operator=(const AxesCorner&) = delete;

  /// Turns the axes as `scene` looks. Call before each render.
  void follow(vtkCamera& scene);

private:
  vtkNew<vtkRenderer> m_renderer;
  vtkNew<vtkAxesActor> m_axes;
};

} // namespace mocap::ui
