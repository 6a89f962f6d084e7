#include "views/label_layer.h"

#include "document/take_document.h"
#include "views/drawn_positions.h"
#include "document/layout_highlight.h"
#include "views/layout_highlight_colors.h"
#include "views/selection_palette.h"

#include <vtkBillboardTextActor3D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkStdString.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

LabelLayer::LabelLayer(vtkRenderer* renderer, const TakeDocument& document, const DrawnPositions& positions)
    : m_renderer(renderer), m_document(document), m_positions(positions)
{
}

LabelLayer::~LabelLayer()
{
  for (auto& label : m_labels)
    m_renderer->RemoveActor(label);
}

void LabelLayer::makeLabels(const std::vector<Eigen::Index>& markers, const std::vector<QColor>& colors)
{
  const Take& take = m_document.take();
  for (auto& label : m_labels)
    m_renderer->RemoveActor(label);
  m_labels.clear();
  m_markers = markers;
  m_colors = colors;
  m_texts.clear();
  for (std::size_t i = 0; i < markers.size(); ++i) {
    auto label = vtkSmartPointer<vtkBillboardTextActor3D>::New();
    label->SetInput(take.label(markers[i]).c_str());
    vtkTextProperty* text = label->GetTextProperty();
    text->SetFontSize(14);
    text->SetColor(static_cast<double>(colors[i].redF()), static_cast<double>(colors[i].greenF()),
                   static_cast<double>(colors[i].blueF()));
    text->SetBold(true);
    text->SetShadow(true);
    m_renderer->AddActor(label);
    m_labels.push_back(label);
    m_texts.push_back(take.label(markers[i]));
  }
}

void LabelLayer::update(Eigen::Index frame, const LayoutHighlight& highlight, const Eigen::Vector3d& lift)
{
  const Take& take = m_document.take();
  const auto& selection = m_document.selection();
  // Selected markers in their palette colours, then the kept markers of a layout highlight.
  std::vector<Eigen::Index> markers = selection;
  std::vector<QColor> colors;
  for (std::size_t i = 0; i < selection.size(); ++i)
    colors.push_back(selectionPaletteColor(i));
  for (std::size_t m = 0; m < highlight.kept.size(); ++m)
    if (highlight.kept[m] && !std::binary_search(selection.begin(), selection.end(), static_cast<Eigen::Index>(m))) {
      markers.push_back(static_cast<Eigen::Index>(m));
      colors.push_back(layoutKeptColor());
    }
  bool remake = markers != m_markers || colors != m_colors;
  for (std::size_t i = 0; !remake && i < markers.size(); ++i)
    remake = m_texts[i] != take.label(markers[i]);
  if (remake)
    makeLabels(markers, colors);
  for (std::size_t i = 0; i < m_labels.size(); ++i) {
    const Eigen::Index m = m_markers[i];
    const bool visible = frame < take.frameCount() && m < take.markerCount() && take.isValid(frame, m) &&
                         !m_document.isHidden(m);
    m_labels[i]->SetVisibility(visible);
    if (!visible)
      continue;
    const Eigen::Vector3d lifted = m_positions.at(frame, m) + lift;
    m_labels[i]->SetPosition(lifted.x(), lifted.y(), lifted.z());
  }
}

void LabelLayer::keepInView()
{
  const int* size = m_renderer->GetSize();
  const int dpi = m_renderer->GetRenderWindow()->GetDPI();
  for (const auto& label : m_labels) {
    label->SetDisplayOffset(0, 0);
    if (!label->GetVisibility())
      continue;
    const double* position = label->GetPosition();
    m_renderer->SetWorldPoint(position[0], position[1], position[2], 1.0);
    m_renderer->WorldToDisplay();
    const double* anchor = m_renderer->GetDisplayPoint();
    if (anchor[0] < 0.0 || anchor[1] < 0.0 || anchor[0] > size[0] || anchor[1] > size[1])
      continue;  // its marker is out of view: no label dragged in
    int box[4] = {0, 0, 0, 0};  // xmin, xmax, ymin, ymax around the anchor, in pixels
    if (!vtkTextRenderer::GetInstance()->GetBoundingBox(label->GetTextProperty(), vtkStdString(label->GetInput()), box,
                                                        dpi))
      continue;
    const auto shift = [](double at, int low, int high, int room) {
      const int over = static_cast<int>(std::ceil(at)) + high - room;
      if (over > 0)
        return -over;
      const int under = -static_cast<int>(std::floor(at)) - low;
      return under > 0 ? under : 0;
    };
    label->SetDisplayOffset(shift(anchor[0], box[0], box[1], size[0]), shift(anchor[1], box[2], box[3], size[1]));
  }
}

} // namespace mocap::ui
