#pragma once

#include <Eigen/Core>

#include <QColor>

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkBillboardTextActor3D;
class vtkRenderer;

namespace mocap::ui {

class DrawnPositions;
class TakeDocument;
struct LayoutHighlight;

/// Marker labels in a VTK renderer (the 3D view's): each selected marker's in its selection colour
/// (selection_palette.h), then each kept marker's of a layout highlight in its colour, as text
/// facing the camera a little above the marker. The text actors are made again only when the
/// labelled markers, their colours or labels change: rasterising text every frame would dominate
/// playback. An update is O(#labels) otherwise.
class LabelLayer
{
public:
  /// Draws into `renderer`; the destructor removes what it added (the renderer is held).
  LabelLayer(vtkRenderer* renderer, const TakeDocument& document, const DrawnPositions& positions);
  ~LabelLayer();
  LabelLayer(const LabelLayer&) = delete;
  LabelLayer& operator=(const LabelLayer&) = delete;

  /// Labels the markers drawn in `frame`, each `lift` (scene units) above its marker.
  void update(Eigen::Index frame, const LayoutHighlight& highlight, const Eigen::Vector3d& lift);
  /// Shifts each shown label that the view's edge would cut back inside, as long as its marker is
  /// in view (a label sits above and right of its marker, and Reset Camera puts the outermost
  /// markers at the edges). Call before each render: it depends on the camera. O(#labels).
  void keepInView();

private:
  void makeLabels(const std::vector<Eigen::Index>& markers, const std::vector<QColor>& colors);

  vtkSmartPointer<vtkRenderer> m_renderer;
  const TakeDocument& m_document;
  const DrawnPositions& m_positions;
  std::vector<vtkSmartPointer<vtkBillboardTextActor3D>> m_labels;  // one per labelled marker
  std::vector<Eigen::Index> m_markers;
  std::vector<std::string> m_texts;
  std::vector<QColor> m_colors;
};

} // namespace mocap::ui
