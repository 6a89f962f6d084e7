#include "views/link_layer.h"

#include "document/take_document.h"
#include "views/drawn_positions.h"

#include "mocap/model/marker_set.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

namespace mocap::ui {

LinkLayer::LinkLayer(vtkRenderer* renderer, const TakeDocument& document, const DrawnPositions& positions)
    : SceneLayer(renderer, document, positions)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(m_lines);
  m_actor->SetMapper(mapper);
  m_actor->GetProperty()->SetColor(0.55, 0.6, 0.7);
  m_actor->GetProperty()->SetOpacity(0.6);
  m_actor->GetProperty()->SetLineWidth(1.0f);
  m_actor->SetVisibility(false);
}

LinkLayer::~LinkLayer() = default;

void LinkLayer::setVisible(bool visible)
{
  m_visible = visible;
  if (visible && m_links.empty())
    findLinks();
  m_actor->SetVisibility(visible);
}

void LinkLayer::forget()
{
  m_links.clear();
  if (m_visible)
    findLinks();
}

void LinkLayer::findLinks()
{
  const Take& take = m_document.take();
  m_links.clear();
  const Eigen::Index frame = take.empty() ? -1 : mostCompleteFrame(take);
  if (frame >= 0)  // none: no marker is ever valid, nothing to link
    m_links = nearestNeighbourLinks(take, frame);
}

void LinkLayer::update(Eigen::Index frame)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  const Take& take = m_document.take();
  if (m_visible && frame < take.frameCount()) {
    for (const auto& [a, b] : m_links) {
      if (a >= take.markerCount() || b >= take.markerCount() || !take.isValid(frame, a) || !take.isValid(frame, b) ||
          m_document.isHidden(a) || m_document.isHidden(b))
        continue;
      const vtkIdType ends[2] = {points->InsertNextPoint(m_positions.at(frame, a).data()),
                                 points->InsertNextPoint(m_positions.at(frame, b).data())};
      lines->InsertNextCell(2, ends);
    }
  }
  m_lines->SetPoints(points);
  m_lines->SetLines(lines);
  m_lines->Modified();
}

} // namespace mocap::ui
