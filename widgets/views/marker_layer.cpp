#include "views/marker_layer.h"

#include "document/take_document.h"
#include "views/drawn_positions.h"
#include "views/layout_highlight_colors.h"
#include "views/sample_colors.h"
#include "views/selection_palette.h"

#include "mocap/model/marker_points.h"
#include "mocap/model/marker_set.h"

#include <vtkActor.h>
#include <vtkGlyph3DMapper.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <limits>

namespace mocap::ui {

double takeDiagonal(const Take& take, Eigen::Index frame)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Index m : markerPoints(take)) {
    Eigen::Index f = frame;
    if (!take.isValid(f, m)) {
      const auto column = take.valid().col(m);
      f = -1;
      for (Eigen::Index i = 0; i < take.frameCount(); ++i)
        if (column(i)) {
          f = i;
          break;
        }
      if (f < 0)
        continue;
    }
    lo = lo.cwiseMin(take.position(f, m));
    hi = hi.cwiseMax(take.position(f, m));
  }
  return lo.x() <= hi.x() ? std::max((hi - lo).norm(), 1e-6) : 1.0;
}

MarkerLayer::MarkerLayer(vtkRenderer* renderer, const TakeDocument& document, const DrawnPositions& positions)
    : SceneLayer(renderer, document, positions)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  sphere->SetRadius(1.0);
  m_colors->SetNumberOfComponents(3);
  m_colors->SetName("colors");
  m_markers->SetPoints(m_points);
  m_markers->GetPointData()->SetScalars(m_colors);
  m_mapper->SetInputData(m_markers);
  m_mapper->SetSourceConnection(sphere->GetOutputPort());
  m_mapper->SetScalarModeToUsePointData();
  m_mapper->ScalingOn();
  m_mapper->SetScaleModeToNoDataScaling();  // every sphere the same size: ScaleFactor
  m_actor->SetMapper(m_mapper);
  m_actor->GetProperty()->SetSpecular(0.3);
}

MarkerLayer::~MarkerLayer() = default;

void MarkerLayer::setRadius(double radius)
{
  m_mapper->SetScaleFactor(radius);  // the glyph is a unit sphere
}

QColor MarkerLayer::colorAt(Eigen::Index frame, Eigen::Index marker, const std::vector<bool>& flagged,
                            const LayoutHighlight& highlight) const
{
  const Take& take = m_document.take();
  const auto& selection = m_document.selection();
  if (std::binary_search(selection.begin(), selection.end(), marker))
    return selectedMarkerColor(selection, marker);
  if (!highlight.empty())
    return layoutHighlightColor(highlight, marker);
  if (flagged[static_cast<std::size_t>(marker)])
    return colorScheme().flagged;
  // Unlabelled points (fragments waiting for a label) stand apart from every labelled state.
  if (isUnlabelledLabel(take.label(marker)))
    return {200, 130, 255};
  return stateColor(take.state(frame, marker));
}

void MarkerLayer::update(Eigen::Index frame, const LayoutHighlight& highlight)
{
  const Take& take = m_document.take();
  m_points->Reset();
  m_colors->Reset();
  m_drawnMarkers.clear();
  if (frame < take.frameCount()) {
    std::vector<bool> flagged(static_cast<std::size_t>(take.markerCount()), false);
    for (const auto& [marker, flagFrame] : m_document.flags())
      if (flagFrame == frame && marker < take.markerCount())
        flagged[static_cast<std::size_t>(marker)] = true;
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      if (!take.isValid(frame, m) || m_document.isHidden(m))
        continue;
      m_points->InsertNextPoint(m_positions.at(frame, m).data());
      const QColor color = colorAt(frame, m, flagged, highlight);
      const unsigned char rgb[3] = {static_cast<unsigned char>(color.red()), static_cast<unsigned char>(color.green()),
                                    static_cast<unsigned char>(color.blue())};
      m_colors->InsertNextTypedTuple(rgb);
      m_drawnMarkers.push_back(m);
    }
  }
  m_points->Modified();
  m_colors->Modified();
  m_markers->Modified();
}

Eigen::Vector3d MarkerLayer::point(std::size_t index) const
{
  Eigen::Vector3d p;
  m_points->GetPoint(static_cast<vtkIdType>(index), p.data());
  return p;
}

std::optional<std::size_t> MarkerLayer::indexOf(Eigen::Index marker) const
{
  const auto it = std::find(m_drawnMarkers.begin(), m_drawnMarkers.end(), marker);
  if (it == m_drawnMarkers.end())
    return std::nullopt;
  return static_cast<std::size_t>(it - m_drawnMarkers.begin());
}

std::optional<QColor> MarkerLayer::colorOf(Eigen::Index marker) const
{
  const std::optional<std::size_t> index = indexOf(marker);
  if (!index)
    return std::nullopt;
  unsigned char rgb[3];
  m_colors->GetTypedTuple(static_cast<vtkIdType>(*index), rgb);
  return QColor(rgb[0], rgb[1], rgb[2]);
}

} // namespace mocap::ui
