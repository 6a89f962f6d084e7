#include "views/camera_framing.h"

#include <vtkCamera.h>
#include <vtkActor.h>
#include <vtkMath.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mocap::ui {

ViewDirection facingDirection(const std::vector<Eigen::Vector3d>& points, int upAxis)
{
  ViewDirection direction;
  const Eigen::Vector3d labUp = Eigen::Vector3d::Unit(upAxis == 1 ? 1 : 2);
  if (points.empty()) {
    direction.up = labUp;
    direction.forward = upAxis == 1 ? Eigen::Vector3d(-Eigen::Vector3d::UnitZ()) : Eigen::Vector3d(Eigen::Vector3d::UnitY());
    return direction;
  }
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points)
    centre += p;
  centre /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : points)
    covariance += (p - centre) * (p - centre).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  Eigen::Vector3d normal = solver.eigenvectors().col(0);
  double front = 0.0, back = 0.0;
  for (const Eigen::Vector3d& p : points) {
    const double d = normal.dot(p - centre);
    front = std::max(front, d);
    back = std::max(back, -d);
  }
  if (back > front)
    normal = -normal;
  // The eye sits on the side the normal points to, so it looks along its opposite.
  direction.forward = -normal;
  direction.up = std::abs(labUp.dot(normal)) > 0.95 ? Eigen::Vector3d::Unit(upAxis == 2 ? 1 : 2) : labUp;
  return direction;
}

void fitCamera(vtkCamera& camera, const std::vector<Eigen::Vector3d>& points, const ViewDirection& direction,
               double aspect, double radius, double margin)
{
  const Eigen::Vector3d forward = direction.forward.normalized();
  const Eigen::Vector3d up = (direction.up - direction.up.dot(forward) * forward).normalized();
  const Eigen::Vector3d right = forward.cross(up);
  if (points.empty() || !up.allFinite())
    return;
  // The box of the points in the camera's axes; its centre is the focal point.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Vector3d q(p.dot(right), p.dot(up), p.dot(forward));
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const Eigen::Vector3d mid = (lo + hi) / 2.0;
  const Eigen::Vector3d focal = mid.x() * right + mid.y() * up + mid.z() * forward;
  aspect = aspect > 0.0 && std::isfinite(aspect) ? aspect : 1.0;
  const double keep = std::clamp(1.0 - margin, 0.1, 1.0);
  const double depth = hi.z() - lo.z();
  double distance = 0.0;
  if (camera.GetParallelProjection()) {
    double half = 0.0;
    for (const Eigen::Vector3d& p : points) {
      const Eigen::Vector3d q = p - focal;
      half = std::max({half, (std::abs(q.dot(up)) + radius) / keep, (std::abs(q.dot(right)) + radius) / (keep * aspect)});
    }
    camera.SetParallelScale(std::max(half, 1e-9));
    distance = depth + 4.0 * radius + half;
  } else {
    // A point at depth z in front of the focal plane is inside when |x| + r ≤ tan · (D + z): the
    // nearest eye distance D that holds for every point and both axes.
    const double tanY = std::tan(vtkMath::RadiansFromDegrees(camera.GetViewAngle()) / 2.0) * keep;
    const double tanX = tanY * aspect;
    distance = depth / 2.0 + 2.0 * radius;  // the eye stays out of the cloud
    for (const Eigen::Vector3d& p : points) {
      const Eigen::Vector3d q = p - focal;
      const double z = q.dot(forward);
      distance = std::max({distance, (std::abs(q.dot(right)) + radius) / tanX - z, (std::abs(q.dot(up)) + radius) / tanY - z});
    }
  }
  const Eigen::Vector3d eye = focal - std::max(distance, 1e-9) * forward;
  camera.SetFocalPoint(focal.data());
  camera.SetPosition(eye.data());
  camera.SetViewUp(up.data());
  camera.OrthogonalizeViewUp();
}

std::vector<Eigen::Vector3d> actorBoxCorners(vtkRenderer& renderer, const std::vector<vtkProp*>& skip)
{
  std::vector<Eigen::Vector3d> corners;
  vtkPropCollection* props = renderer.GetViewProps();
  props->InitTraversal();
  while (vtkProp* prop = props->GetNextProp()) {
    if (std::find(skip.begin(), skip.end(), prop) != skip.end() || !prop->GetVisibility() || !vtkActor::SafeDownCast(prop))
      continue;
    const double* bounds = prop->GetBounds();
    if (!bounds || !vtkMath::AreBoundsInitialized(bounds))
      continue;
    for (int corner = 0; corner < 8; ++corner)
      corners.emplace_back(bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)]);
  }
  return corners;
}

} // namespace mocap::ui
