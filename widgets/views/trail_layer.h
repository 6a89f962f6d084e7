#pragma once

#include "views/scene_layer.h"

#include <Eigen/Core>

#include <vtkNew.h>

class vtkPolyData;

namespace mocap::ui {

/// The selected markers' trails in a VTK renderer (the 3D view's): each one's drawn path over the
/// frames within ±frames() of the current one, in its selection colour (selection_palette.h), broken
/// at its gaps; hidden markers have none. An update is O(#selected · frames()).
class TrailLayer final : public SceneLayer
{
public:
  TrailLayer(vtkRenderer* renderer, const TakeDocument& document, const DrawnPositions& positions);
  ~TrailLayer();

  /// Frames drawn before and after the current one (0 = no trails; negative counts as 0).
  void setFrames(int frames);
  [[nodiscard]] int frames() const { return m_frames; }
  /// Draws the trails around `frame` (none past the take's end).
  void update(Eigen::Index frame);

private:
  vtkNew<vtkPolyData> m_trails;
  int m_frames = 50;
};

} // namespace mocap::ui
