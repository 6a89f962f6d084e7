#pragma once

#include "mocap/base/length_unit.h"
#include "views/marker_scene.h"
#include "views/scene_settings.h"

#include <QColor>
#include <QWidget>

#include <memory>
#include <optional>

#include <Eigen/Core>

#include <vector>

class QLabel;
class QStackedLayout;

namespace mocap::ui {

class AxesCorner;
class SessionScene;
class TakeDocument;
class ViewState;
class VtkViewport;

/// The 3D view of a document: a VtkViewport drawing the document's MarkerScene (the markers coloured
/// by sample state, selection or layout highlight, the selected markers' trails and labels, the
/// links, in the lab frame or head-stabilized, the camera framed or following the head) with the lab
/// axes in a corner (AxesCorner), kept up to date with the document and, when observed, its
/// ViewState. The widget's own part: picking (click picks the nearest marker, Ctrl+drag a rubber
/// band picks all inside it, Ctrl/Shift adds to the selection), the hovered marker's tooltip, R for
/// Reset Camera, and a line of text in the top-left corner while the view is head-stabilized or
/// follows the head. The session's other layers (SessionScene: face mesh, posed rig) draw into the
/// same renderer (addLayers).
class MarkerView3d final : public QWidget
{
  Q_OBJECT

public:
  explicit MarkerView3d(TakeDocument& document, QWidget* parent = nullptr);
  ~MarkerView3d() override;

  [[nodiscard]] VtkViewport* viewport() const { return m_viewport; }
  /// What the view draws: the document's MarkerScene in the viewport's renderer.
  [[nodiscard]] const MarkerScene& scene() const { return *m_scene; }
  /// Draws as `state` says from now on: up axis, marker size, trails, links, head follow, display
  /// unit, colours and layout highlight, each applied now and on each change, and frames the
  /// camera when it asks (ViewState::resetCamera). The setters below stay for a view without one.
  void observe(const ViewState& state);
  /// Draws `layers` (made on scene()) with the markers: renders when they change and places them
  /// before each render, while both live.
  void addLayers(SessionScene& layers);
  /// Frames drawn before and after the current one for each selected marker (0 = no trails).
  void setTrailFrames(int frames)
  {
    m_scene->setTrailFrames(frames);
    updateFrame();
  }
  [[nodiscard]] int trailFrames() const { return m_scene->trailFrames(); }
  /// Sphere radius as a fraction of the take's size.
  void setMarkerScale(double fraction);
  [[nodiscard]] double markerScale() const { return m_scene->markerScale(); }
  /// Unit of the hover read-out (the take keeps its own units).
  void setDisplayUnit(LengthUnit unit) { m_displayUnit = unit; }
  /// Labelling mode: a click on a drawn marker emits labelPointClicked instead of selecting it.
  void setLabellingMode(bool on) { m_labellingMode = on; }
  [[nodiscard]] bool labellingMode() const { return m_labellingMode; }
  /// Lines between neighbouring markers (each to its nearest three in the most complete frame;
  /// none when no marker is ever valid).
  void setLinksVisible(bool visible)
  {
    m_scene->setLinksVisible(visible);
    updateFrame();
  }
  [[nodiscard]] bool linksVisible() const { return m_scene->linksVisible(); }
  [[nodiscard]] const std::vector<MarkerLink>& links() const { return m_scene->links(); }
  /// Which lab axis points up on screen: 1 = Y, 2 = Z.
  void setUpAxis(int axis);
  [[nodiscard]] int upAxis() const { return m_scene->upAxis(); }
  /// Frames what is drawn at the current frame: frameCamera(current, current) (View ▸ Reset Camera).
  void resetCamera();
  /// Faces the markers drawn over frames first…last (their least-spread side, facingDirection) and
  /// fits the camera so every one of them, and every other actor drawn (face mesh, posed rig), is
  /// inside the view (fitCamera). A view resized before the camera moved is framed again.
  /// O(#frames · #markers), at most 500 frames sampled.
  void frameCamera(Eigen::Index first, Eigen::Index last);
  /// Redraws with the current colorScheme() (sample_colors.h), background included.
  void refreshColors();
  /// Head-stabilized view: draws every marker relative to the head pose estimated from these
  /// reference markers (head_stabilization.h), so only facial motion remains; empty = lab frame.
  /// A view setting: the take is not changed. Returns an error message (the view is then
  /// unchanged) or an empty string. Dropped when markers are added or removed.
  QString setHeadReference(std::vector<Eigen::Index> referenceMarkers);
  [[nodiscard]] const std::vector<Eigen::Index>& headReference() const { return m_scene->positions().headReference(); }
  /// Where marker `marker` is drawn in `frame` (stabilized when the view is).
  [[nodiscard]] Eigen::Vector3d displayPosition(Eigen::Index frame, Eigen::Index marker) const;
  /// The marker drawn nearest to `position` (widget coordinates), within `radius` pixels.
  [[nodiscard]] Eigen::Index markerAt(QPoint position, int radius = 12) const;
  /// The markers drawn inside `rectangle` (widget coordinates), ascending.
  [[nodiscard]] std::vector<Eigen::Index> markersIn(const QRect& rectangle) const;
  /// Where drawn marker `marker` appears in the widget; nullopt when it is not drawn.
  [[nodiscard]] std::optional<QPointF> screenPosition(Eigen::Index marker) const;
  /// Camera follows the head: the focal point tracks the smoothed centroid of the head markers
  /// (guessHeadReferenceMarkers, else every valid marker), keeping orientation and distance, so
  /// the face stays in view while the head moves in the lab frame.
  void setFollowHead(bool on);
  [[nodiscard]] bool followHead() const { return m_scene->follow().on(); }
  /// Where the camera looks in `frame` while following: the mean, over frames within ±0.2 s, of
  /// the centroid of the followed markers' drawn positions (a window mean, so scrubbing back and
  /// forth gives the same view). nullopt when no followed marker is valid near `frame`.
  /// O(window × followed markers).
  [[nodiscard]] std::optional<Eigen::Vector3d> followTarget(Eigen::Index frame) const;
  /// The markers the camera follows.
  [[nodiscard]] const std::vector<Eigen::Index>& followedMarkers() const { return m_scene->follow().markers(); }
  /// The camera's focal point (lab or stabilized coordinates, as drawn).
  [[nodiscard]] Eigen::Vector3d cameraFocalPoint() const;
  /// The colour `marker` is drawn in at the current frame; nullopt when it is not drawn.
  [[nodiscard]] std::optional<QColor> markerColor(Eigen::Index marker) const;
  /// The corner text shown (head-stabilized, following the head); empty when none is shown.
  [[nodiscard]] QString statusText() const;
  /// A planned marker layout over the take: while set, markers are drawn kept (white, labelled)
  /// or dropped (dim grey), and the head reference markers the plan leaves out in blue, instead
  /// of by sample state (none of these is a sample-state colour); selection still shows. One flag
  /// per marker in each; `reference` may be empty. Dropped when markers are added, removed or
  /// another take is opened.
  void setLayoutHighlight(std::vector<bool> kept, std::vector<bool> reference = {});
  void clearLayoutHighlight();
  /// The highlight shown, empty when none.
  [[nodiscard]] const std::vector<bool>& layoutHighlight() const { return m_scene->layoutHighlight().kept; }
  /// The highlight's reference markers left out (empty when none).
  [[nodiscard]] const std::vector<bool>& layoutReference() const { return m_scene->layoutHighlight().reference; }

signals:
  void labelPointClicked(Eigen::Index marker);

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  /// The take was replaced or its markers shifted (MarkerScene::forgetMarkerIndices).
  void forgetMarkerIndices();
  /// Sizes the markers for the take and draws the frame, the camera framed afresh.
  void rebuildScene();
  /// Draws the scene at the document's current frame.
  void updateFrame();
  void updateStatus();
  void showTooltip(QPoint position);
  void onClicked(QPoint position, Qt::KeyboardModifiers modifiers);
  void onRectangle(const QRect& rectangle, Qt::KeyboardModifiers modifiers);
  /// Drawn point `index` (MarkerLayer::drawnMarkers) in widget (logical) coordinates.
  [[nodiscard]] QPointF projected(std::size_t index) const;

  TakeDocument& m_document;
  QStackedLayout* m_stack = nullptr;
  VtkViewport* m_viewport = nullptr;
  QLabel* m_failure = nullptr;
  QLabel* m_status = nullptr;
  std::unique_ptr<MarkerScene> m_scene;  // draws into m_viewport's renderer
  std::unique_ptr<AxesCorner> m_axes;
  bool m_labellingMode = false;
  LengthUnit m_displayUnit = LengthUnit::Millimetre;
  std::optional<CameraState> m_framedCamera;  // as the last framing left it
};

} // namespace mocap::ui
