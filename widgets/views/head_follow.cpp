#include "views/head_follow.h"

#include "document/take_document.h"
#include "views/drawn_positions.h"

#include "mocap/model/marker_points.h"

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

HeadFollow::HeadFollow(const TakeDocument& document, const DrawnPositions& positions)
    : m_document(document), m_positions(positions)
{
}

void HeadFollow::setOn(bool on)
{
  m_on = on;
  if (m_markers.empty())
    chooseMarkers();
}

void HeadFollow::chooseMarkers()
{
  m_markers = m_document.referenceMarkers();
  if (m_markers.empty())  // no head markers: the whole face
    m_markers = markerPoints(m_document.take());
}

std::optional<Eigen::Vector3d> HeadFollow::target(Eigen::Index frame) const
{
  const Take& take = m_document.take();
  if (take.empty() || frame < 0 || frame >= take.frameCount())
    return std::nullopt;
  const auto halfWindow = static_cast<Eigen::Index>(std::lround(0.2 * take.frameRate()));
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Index frames = 0;
  for (Eigen::Index f = std::max<Eigen::Index>(0, frame - halfWindow);
       f <= std::min<Eigen::Index>(take.frameCount() - 1, frame + halfWindow); ++f) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    Eigen::Index count = 0;
    for (Eigen::Index m : m_markers)
      if (m < take.markerCount() && take.isValid(f, m)) {
        centroid += m_positions.at(f, m);
        ++count;
      }
    // A frame counts only with every followed marker: a marker dropping out would jolt the centroid.
    if (count == static_cast<Eigen::Index>(m_markers.size()) && count > 0) {
      sum += centroid / static_cast<double>(count);
      ++frames;
    }
  }
  if (frames == 0)
    return std::nullopt;
  return sum / static_cast<double>(frames);
}

void HeadFollow::aim(vtkRenderer& renderer, Eigen::Index frame) const
{
  if (!m_on)
    return;
  const std::optional<Eigen::Vector3d> aimAt = target(frame);
  if (!aimAt)
    return;
  vtkCamera* camera = renderer.GetActiveCamera();
  Eigen::Vector3d focal, position;
  camera->GetFocalPoint(focal.data());
  camera->GetPosition(position.data());
  const Eigen::Vector3d moved = position + (*aimAt - focal);
  camera->SetFocalPoint(aimAt->data());
  camera->SetPosition(moved.data());
  renderer.ResetCameraClippingRange();
}

} // namespace mocap::ui
