#pragma once

#include "mocap/model/marker_links.h"
#include "views/scene_layer.h"

#include <vtkNew.h>

#include <vector>

class vtkPolyData;

namespace mocap::ui {

/// Lines between neighbouring markers in a VTK renderer (the 3D view's), so the face reads as a
/// surface: each marker to its nearest three in the take's most complete frame
/// (nearestNeighbourLinks), found when first shown for a take; a link is drawn in a frame where
/// both its ends are drawn. Hidden until shown. An update is O(#links).
class LinkLayer final : public SceneLayer
{
public:
  LinkLayer(vtkRenderer* renderer, const TakeDocument& document, const DrawnPositions& positions);
  ~LinkLayer();

  /// Shows or hides the links; showing finds them when not found yet, O(#markers² log #markers).
  void setVisible(bool visible);
  [[nodiscard]] bool visible() const { return m_visible; }
  /// Drops the links (the take was replaced or its markers shifted); found again while shown.
  void forget();
  /// The links found (none when no marker is ever valid, or never shown).
  [[nodiscard]] const std::vector<MarkerLink>& links() const { return m_links; }
  /// Draws the links of `frame` while shown (none past the take's end).
  void update(Eigen::Index frame);

private:
  void findLinks();

  vtkNew<vtkPolyData> m_lines;
  std::vector<MarkerLink> m_links;
  bool m_visible = false;
};

} // namespace mocap::ui
