#include "views/drawn_positions.h"

#include "document/take_document.h"

#include "mocap/cleaning/head_stabilization.h"
#include "mocap/model/marker_points.h"

#include <algorithm>
#include <exception>

namespace mocap::ui {

QString DrawnPositions::setHeadReference(std::vector<Eigen::Index> referenceMarkers)
{
  std::shared_ptr<const HeadMotion> motion;
  if (!referenceMarkers.empty()) {
    try {
      motion = m_document.headMotion(referenceMarkers);
    } catch (const std::exception& e) {
      return QString::fromStdString(e.what());
    }
  }
  m_headReference = std::move(referenceMarkers);
  m_headMotion = std::move(motion);
  return {};
}

void DrawnPositions::clear()
{
  m_headReference.clear();
  m_headMotion.reset();
}

Eigen::Vector3d DrawnPositions::at(Eigen::Index frame, Eigen::Index marker) const
{
  const Eigen::Vector3d p = m_document.take().position(frame, marker);
  if (!m_headMotion)
    return p;
  // The pose maps the reference frame's head onto the captured one; its inverse takes the
  // captured sample back into the reference frame's head.
  return m_headMotion->poses[static_cast<std::size_t>(frame)].inverse() * p;
}

std::vector<Eigen::Vector3d> DrawnPositions::over(Eigen::Index first, Eigen::Index last) const
{
  const Take& take = m_document.take();
  std::vector<Eigen::Vector3d> points;
  const std::vector<Eigen::Index> markers = markerPoints(take);  // model outputs are no positions
  const Eigen::Index step = std::max<Eigen::Index>(1, (last - first + 1) / 500);
  for (Eigen::Index f = first; f <= last; f += step)
    for (const Eigen::Index m : markers)
      if (take.isValid(f, m) && !m_document.isHidden(m))
        points.push_back(at(f, m));
  if (!points.empty())
    return points;
  // Nothing valid in these frames: each marker where it first is.
  for (const Eigen::Index m : markers) {
    const auto column = take.valid().col(m);
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
      if (column(f)) {
        points.push_back(at(f, m));
        break;
      }
  }
  return points;
}

} // namespace mocap::ui
