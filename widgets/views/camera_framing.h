#pragma once

#include <Eigen/Core>

#include <vector>

class vtkCamera;
class vtkProp;
class vtkRenderer;

namespace mocap::ui {

/// Room left between the framed points and each edge of the view, as a fraction of the view's
/// half-width (half-height): markers never touch the border.
inline constexpr double kFramingMargin = 0.06;

/// Where a camera looks along (from the eye towards the points, unit) and which way is up on screen.
struct ViewDirection
{
  Eigen::Vector3d forward = -Eigen::Vector3d::UnitY();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
};

/// The direction the studio faces a cloud of points from: along its axis of least spread (a face
/// is flattest along its normal), from the side the points protrude to (the nose sticks out more
/// than the cheeks recede), with lab axis `upAxis` (1 = Y, 2 = Z) up unless the view looks along
/// it. O(#points).
[[nodiscard]] ViewDirection facingDirection(const std::vector<Eigen::Vector3d>& points, int upAxis);

/// Places `camera` looking along `direction` at the nearest distance from which every point, as a
/// sphere of `radius`, is inside the view: its vertical view angle and the horizontal angle that
/// `aspect` (width / height) gives, each side less `margin`. The view angle is kept (a parallel
/// projection gets its scale instead). The one framing of the 3D view's Reset Camera and of review
/// videos. O(#points).
void fitCamera(vtkCamera& camera, const std::vector<Eigen::Vector3d>& points, const ViewDirection& direction,
               double aspect, double radius, double margin = kFramingMargin);

/// The corners of the boxes of the visible actors `renderer` draws, but for those in `skip` (what
/// is framed by its points instead): how a framing keeps the other actors drawn (face mesh, posed
/// rig) in view. Text and other props that are no vtkActor are left out. O(#props).
[[nodiscard]] std::vector<Eigen::Vector3d> actorBoxCorners(vtkRenderer& renderer, const std::vector<vtkProp*>& skip);

} // namespace mocap::ui
