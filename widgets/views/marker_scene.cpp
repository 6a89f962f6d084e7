#include "views/marker_scene.h"

#include "document/take_document.h"
#include "views/camera_framing.h"
#include "views/label_layer.h"
#include "views/link_layer.h"
#include "views/marker_layer.h"
#include "views/trail_layer.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>

namespace mocap::ui {

MarkerScene::MarkerScene(vtkRenderer* renderer, const TakeDocument& document)
    : m_renderer(renderer), m_document(document), m_positions(document), m_follow(document, m_positions),
      m_markers(std::make_unique<MarkerLayer>(renderer, document, m_positions)),
      m_trails(std::make_unique<TrailLayer>(renderer, document, m_positions)),
      m_links(std::make_unique<LinkLayer>(renderer, document, m_positions)),
      m_labels(std::make_unique<LabelLayer>(renderer, document, m_positions))
{
}

MarkerScene::~MarkerScene() = default;

void MarkerScene::setTrailFrames(int frames)
{
  m_trails->setFrames(frames);
}

int MarkerScene::trailFrames() const
{
  return m_trails->frames();
}

void MarkerScene::setMarkerScale(double fraction)
{
  m_markerScale = std::clamp(fraction, 1e-4, 0.2);
}

void MarkerScene::setLinksVisible(bool visible)
{
  m_links->setVisible(visible);
}

bool MarkerScene::linksVisible() const
{
  return m_links->visible();
}

const std::vector<MarkerLink>& MarkerScene::links() const
{
  return m_links->links();
}

void MarkerScene::setLayoutHighlight(std::vector<bool> kept, std::vector<bool> reference)
{
  m_highlight = LayoutHighlight::forTake(std::move(kept), std::move(reference), m_document.take().markerCount());
}

void MarkerScene::sizeToTake()
{
  m_takeSize = takeDiagonal(m_document.take(), m_document.currentFrame());
  m_markers->setRadius(m_markerScale * m_takeSize);
}

void MarkerScene::forgetMarkerIndices()
{
  m_highlight = {};
  m_positions.clear();
  m_follow.chooseMarkers();
  m_links->forget();
}

void MarkerScene::update()
{
  const Eigen::Index frame = m_document.currentFrame();
  m_markers->update(frame, m_highlight);
  m_links->update(frame);
  m_trails->update(frame);
  m_labels->update(frame, m_highlight, 2.5 * m_markerScale * m_takeSize * Eigen::Vector3d::Unit(m_upAxis));
  m_follow.aim(*m_renderer, frame);
}

bool MarkerScene::frameCamera(Eigen::Index first, Eigen::Index last, QSize viewSize)
{
  const Take& take = m_document.take();
  if (take.empty())
    return false;
  first = std::clamp<Eigen::Index>(first, 0, take.frameCount() - 1);
  last = std::clamp<Eigen::Index>(last, first, take.frameCount() - 1);
  std::vector<Eigen::Vector3d> points = m_positions.over(first, last);
  const ViewDirection direction = facingDirection(points, m_upAxis);  // the markers decide where the face looks
  const std::vector<Eigen::Vector3d> others =
      actorBoxCorners(*m_renderer, {m_markers->actor(), m_trails->actor(), m_links->actor()});
  points.insert(points.end(), others.begin(), others.end());
  const double aspect = viewSize.isEmpty() ? 1.0 : static_cast<double>(viewSize.width()) / viewSize.height();
  fitCamera(*m_renderer->GetActiveCamera(), points, direction, aspect, m_markerScale * m_takeSize);
  m_renderer->ResetCameraClippingRange();
  return true;
}

void MarkerScene::beforeRender()
{
  m_labels->keepInView();
}

} // namespace mocap::ui
