#pragma once

#include "views/drawn_positions.h"
#include "views/head_follow.h"
#include "document/layout_highlight.h"

#include "mocap/model/marker_links.h"

#include <QSize>

#include <Eigen/Core>

#include <memory>
#include <vector>

class vtkRenderer;

namespace mocap::ui {

class LabelLayer;
class LinkLayer;
class MarkerLayer;
class TakeDocument;
class TrailLayer;

/// A document's markers drawn in a VTK renderer, with no widget: the layers of the current frame
/// (MarkerLayer, TrailLayer, LinkLayer, LabelLayer, in that order, so translucent ones blend the same
/// way each time) where DrawnPositions puts the markers (the lab frame or head-stabilized), sized to
/// the take, with a planned layout's highlight, and the camera framed on what is drawn
/// (camera_framing) or following the head (HeadFollow). The 3D view (MarkerView3d) draws one in its
/// viewport and tells it when the document or its settings change; other layers (face mesh, posed
/// rig) draw into the same renderer. Nothing here renders: the owner of the render window does.
class MarkerScene
{
public:
  MarkerScene(vtkRenderer* renderer, const TakeDocument& document);
  ~MarkerScene();
  MarkerScene(const MarkerScene&) = delete;
  MarkerScene& operator=(const MarkerScene&) = delete;

  /// The renderer the layers draw in (other layers, the face mesh and posed rig, draw there too).
  [[nodiscard]] vtkRenderer* renderer() const { return m_renderer; }
  [[nodiscard]] DrawnPositions& positions() { return m_positions; }
  [[nodiscard]] const DrawnPositions& positions() const { return m_positions; }
  [[nodiscard]] HeadFollow& follow() { return m_follow; }
  [[nodiscard]] const HeadFollow& follow() const { return m_follow; }
  /// The layers: the markers drawn now (for picking and their colours), the trails, the links.
  [[nodiscard]] const MarkerLayer& markerLayer() const { return *m_markers; }
  [[nodiscard]] const TrailLayer& trailLayer() const { return *m_trails; }
  [[nodiscard]] const LinkLayer& linkLayer() const { return *m_links; }

  /// Frames drawn before and after the current one for each selected marker (0 = no trails).
  void setTrailFrames(int frames);
  [[nodiscard]] int trailFrames() const;
  /// Sphere radius as a fraction of the take's size, clamped to 0.0001…0.2.
  void setMarkerScale(double fraction);
  [[nodiscard]] double markerScale() const { return m_markerScale; }
  /// Which lab axis points up on screen: 1 = Y, else Z (2).
  void setUpAxis(int axis) { m_upAxis = axis == 1 ? 1 : 2; }
  [[nodiscard]] int upAxis() const { return m_upAxis; }
  void setLinksVisible(bool visible);
  [[nodiscard]] bool linksVisible() const;
  [[nodiscard]] const std::vector<MarkerLink>& links() const;
  /// A planned layout over the take (LayoutHighlight::forTake); empty `kept` clears it.
  void setLayoutHighlight(std::vector<bool> kept, std::vector<bool> reference);
  [[nodiscard]] const LayoutHighlight& layoutHighlight() const { return m_highlight; }

  /// Sizes the markers for the take at its current frame (takeDiagonal). O(#markers).
  void sizeToTake();
  /// Drops what holds marker indices (layout highlight, head reference, links; links are found
  /// again while shown) and picks the markers to follow again: the take was replaced or its
  /// markers shifted.
  void forgetMarkerIndices();
  /// Draws every layer at the document's current frame, and aims the camera there while
  /// following the head. O(#markers + #selected · trail frames + #links).
  void update();
  /// Points the camera at the markers drawn over frames first…last from their least-spread side
  /// (facingDirection) and fits it so every one of them, and every other actor drawn (face mesh,
  /// posed rig), is inside a view of `viewSize` (fitCamera). O(#frames · #markers), at most 500
  /// frames sampled. False for an empty take (the camera is not moved).
  bool frameCamera(Eigen::Index first, Eigen::Index last, QSize viewSize);
  /// What depends on the camera (labels kept inside the view): call before each render.
  void beforeRender();

private:
  vtkRenderer* m_renderer;
  const TakeDocument& m_document;
  DrawnPositions m_positions;
  HeadFollow m_follow;
  LayoutHighlight m_highlight;
  std::unique_ptr<MarkerLayer> m_markers;
  std::unique_ptr<TrailLayer> m_trails;
  std::unique_ptr<LinkLayer> m_links;
  std::unique_ptr<LabelLayer> m_labels;
  double m_takeSize = 1.0;  // diagonal of the take's markers, fixed per take
  double m_markerScale = 0.012;
  int m_upAxis = 2;
};

} // namespace mocap::ui
