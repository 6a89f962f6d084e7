#pragma once

#include "views/scene_layer.h"

#include <Eigen/Core>

#include <QColor>

#include <vtkNew.h>

#include <optional>
#include <vector>

class vtkGlyph3DMapper;
class vtkPoints;
class vtkPolyData;
class vtkUnsignedCharArray;

namespace mocap {
class Take;
}

namespace mocap::ui {

struct LayoutHighlight;

/// The diagonal of the box holding every marker point's sample at `frame` (else its first valid
/// one; model outputs are no positions): the take's size, which the marker radius is a fraction of.
/// O(#markers), and O(#frames) per marker missing at `frame`.
[[nodiscard]] double takeDiagonal(const Take& take, Eigen::Index frame);

/// A frame's markers as spheres of one radius in a VTK renderer (the 3D view's), where
/// DrawnPositions puts them: selected markers in their curve colours (selection_palette.h); under a
/// layout highlight kept, reference or dropped (layout_highlight_colors.h); else flagged as a bad point,
/// unlabelled, or by sample state (sample_colors.h). Missing and hidden markers are not drawn. It
/// remembers which marker each drawn point is, for picking. An update is O(#markers + #flags).
class MarkerLayer final : public SceneLayer
{
public:
  MarkerLayer(vtkRenderer* renderer, const TakeDocument& document, const DrawnPositions& positions);
  ~MarkerLayer();

  /// The spheres' radius, scene units.
  void setRadius(double radius);
  /// Draws the markers of `frame` (nothing past the take's end).
  void update(Eigen::Index frame, const LayoutHighlight& highlight);
  /// The marker of each drawn point, in drawing order.
  [[nodiscard]] const std::vector<Eigen::Index>& drawnMarkers() const { return m_drawnMarkers; }
  /// Where drawn point `index` is (as the renderer holds it, single precision).
  [[nodiscard]] Eigen::Vector3d point(std::size_t index) const;
  /// The drawn point of `marker`; nullopt when it is not drawn. O(#drawn).
  [[nodiscard]] std::optional<std::size_t> indexOf(Eigen::Index marker) const;
  /// The colour `marker` is drawn in; nullopt when it is not drawn. O(#drawn).
  [[nodiscard]] std::optional<QColor> colorOf(Eigen::Index marker) const;

private:
  [[nodiscard]] QColor colorAt(Eigen::Index frame, Eigen::Index marker, const std::vector<bool>& flagged,
                               const LayoutHighlight& highlight) const;

  vtkNew<vtkPoints> m_points;
  vtkNew<vtkUnsignedCharArray> m_colors;
  vtkNew<vtkPolyData> m_markers;
  vtkNew<vtkGlyph3DMapper> m_mapper;
  std::vector<Eigen::Index> m_drawnMarkers;  // point id -> marker
};

} // namespace mocap::ui
