#include "views/trail_layer.h"

#include "document/take_document.h"
#include "views/drawn_positions.h"
#include "views/selection_palette.h"

#include <QColor>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <vector>

namespace mocap::ui {

namespace {

unsigned char channel(int value)
{
  return static_cast<unsigned char>(std::clamp(value, 0, 255));
}

} // namespace

TrailLayer::TrailLayer(vtkRenderer* renderer, const TakeDocument& document, const DrawnPositions& positions)
    : SceneLayer(renderer, document, positions)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(m_trails);
  mapper->SetScalarModeToUseCellData();  // each trail in its marker's colour
  m_actor->SetMapper(mapper);
  m_actor->GetProperty()->SetOpacity(0.7);
  m_actor->GetProperty()->SetLineWidth(2.0f);
}

TrailLayer::~TrailLayer() = default;

void TrailLayer::setFrames(int frames)
{
  m_frames = std::max(frames, 0);
}

void TrailLayer::update(Eigen::Index frame)
{
  const Take& take = m_document.take();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  const auto& selection = m_document.selection();
  if (m_frames > 0 && frame < take.frameCount()) {
    for (std::size_t i = 0; i < selection.size(); ++i) {
      const Eigen::Index m = selection[i];
      if (m_document.isHidden(m))
        continue;
      const QColor color = selectionPaletteColor(i);
      const unsigned char rgb[3] = {channel(color.red()), channel(color.green()), channel(color.blue())};
      const Eigen::Index first = std::max<Eigen::Index>(0, frame - m_frames);
      const Eigen::Index last = std::min<Eigen::Index>(take.frameCount() - 1, frame + m_frames);
      std::vector<vtkIdType> run;
      auto flush = [&] {
        if (run.size() > 1) {
          lines->InsertNextCell(static_cast<vtkIdType>(run.size()), run.data());
          colors->InsertNextTypedTuple(rgb);
        }
        run.clear();
      };
      for (Eigen::Index f = first; f <= last; ++f) {
        if (!take.isValid(f, m)) {
          flush();  // a gap breaks the trail
          continue;
        }
        run.push_back(points->InsertNextPoint(m_positions.at(f, m).data()));
      }
      flush();
    }
  }
  m_trails->SetPoints(points);
  m_trails->SetLines(lines);
  m_trails->GetCellData()->SetScalars(colors);
  m_trails->Modified();
}

} // namespace mocap::ui
