#pragma once

#include "mocap/cleaning/head_stabilization.h"
#include "views/scene_settings.h"

#include <QColor>
#include <QWidget>

#include <memory>
#include <optional>

#include <Eigen/Core>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class QLabel;
class QStackedLayout;
class vtkActor;
class vtkAxesActor;
class vtkBillboardTextActor3D;
class vtkGlyph3DMapper;
class vtkPoints;
class vtkPolyData;
class vtkRenderer;
class vtkUnsignedCharArray;

namespace mocap::ui {

class TakeDocument;
class ViewState;
class VtkViewport;

/// The 3D viewport: the current frame's markers as spheres coloured by sample state
/// (original, filled, smoothed, edited, flagged as a bad point); selected markers in their curve
/// colours (selection_palette.h) and labelled, with trails over ±trailFrames frames in the same
/// colours; an axes marker in the corner and, while the view is head-stabilized or follows the
/// head, a line of text saying so in the top-left corner.
/// Missing samples are not drawn. Click picks the nearest marker, Ctrl+drag a rubber band picks all inside it (Ctrl/Shift adds to the
/// selection); the camera faces the take's markers from the side they protrude to.
class MarkerView3d final : public QWidget
{
  Q_OBJECT

public:
  explicit MarkerView3d(TakeDocument& document, QWidget* parent = nullptr);
  ~MarkerView3d() override;

  [[nodiscard]] VtkViewport* viewport() const { return m_viewport; }
  /// Draws as `state` says from now on: up axis, marker size, trails, links, head follow, display
  /// unit, colours and layout highlight, each applied now and on each change, and frames the
  /// camera when it asks (ViewState::resetCamera). The setters below stay for a view without one.
  void observe(const ViewState& state);
  /// Frames drawn before and after the current one for each selected marker (0 = no trails).
  void setTrailFrames(int frames);
  [[nodiscard]] int trailFrames() const { return m_trailFrames; }
  /// Sphere radius as a fraction of the take's size.
  void setMarkerScale(double fraction);
  [[nodiscard]] double markerScale() const { return m_markerScale; }
  /// Unit of the hover read-out (the take keeps its own units).
  void setDisplayUnit(LengthUnit unit) { m_displayUnit = unit; }
  /// Labelling mode: a click on a drawn marker emits labelPointClicked instead of selecting it.
  void setLabellingMode(bool on) { m_labellingMode = on; }
  [[nodiscard]] bool labellingMode() const { return m_labellingMode; }
  /// Lines between neighbouring markers (each to its nearest three in the most complete frame;
  /// none when no marker is ever valid).
  void setLinksVisible(bool visible);
  [[nodiscard]] bool linksVisible() const { return m_linksVisible; }
  [[nodiscard]] const std::vector<std::pair<Eigen::Index, Eigen::Index>>& links() const { return m_links; }
  /// Which lab axis points up on screen: 1 = Y, 2 = Z.
  void setUpAxis(int axis);
  [[nodiscard]] int upAxis() const { return m_upAxis; }
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
  [[nodiscard]] const std::vector<Eigen::Index>& headReference() const { return m_headReference; }
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
  [[nodiscard]] bool followHead() const { return m_followHead; }
  /// Where the camera looks in `frame` while following: the mean, over frames within ±0.2 s, of
  /// the centroid of the followed markers' drawn positions (a window mean, so scrubbing back and
  /// forth gives the same view). nullopt when no followed marker is valid near `frame`.
  /// O(window × followed markers).
  [[nodiscard]] std::optional<Eigen::Vector3d> followTarget(Eigen::Index frame) const;
  /// The markers the camera follows.
  [[nodiscard]] const std::vector<Eigen::Index>& followedMarkers() const { return m_followMarkers; }
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
  [[nodiscard]] const std::vector<bool>& layoutHighlight() const { return m_layoutKept; }
  /// The highlight's reference markers left out (empty when none).
  [[nodiscard]] const std::vector<bool>& layoutReference() const { return m_layoutReference; }

signals:
  void labelPointClicked(Eigen::Index marker);

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  /// Where the markers (not hidden, not model outputs) are drawn over frames first…last, at most
  /// 500 frames sampled; each marker's first valid sample when none is valid there.
  [[nodiscard]] std::vector<Eigen::Vector3d> drawnPositions(Eigen::Index first, Eigen::Index last) const;
  /// Drops what holds marker indices (layout highlight, head reference, links) and works out the
  /// markers to follow again: the take was replaced or its markers shifted.
  void forgetMarkerIndices();
  void rebuildScene();
  void updateFrame();
  void updateTrails();
  void updateLinks();
  void computeLinks();
  void updateLabels();
  void keepLabelsInView();
  void updateStatus();
  void updateFollow();
  /// The document's reference markers (the whole face when it has none). O(#markers).
  [[nodiscard]] std::vector<Eigen::Index> markersToFollow() const;
  void onClicked(QPoint position, Qt::KeyboardModifiers modifiers);
  void onRectangle(const QRect& rectangle, Qt::KeyboardModifiers modifiers);
  /// Drawn point `id` in widget (logical) coordinates.
  [[nodiscard]] QPointF projected(vtkIdType id) const;
  [[nodiscard]] double takeSize() const;

  TakeDocument& m_document;
  QStackedLayout* m_stack = nullptr;
  VtkViewport* m_viewport = nullptr;
  QLabel* m_failure = nullptr;
  vtkNew<vtkPoints> m_points;
  vtkNew<vtkUnsignedCharArray> m_colors;
  vtkNew<vtkPolyData> m_markers;
  vtkNew<vtkGlyph3DMapper> m_mapper;
  vtkNew<vtkActor> m_actor;
  vtkNew<vtkPolyData> m_trails;
  vtkNew<vtkActor> m_trailActor;
  vtkNew<vtkRenderer> m_axesRenderer;
  vtkNew<vtkAxesActor> m_axes;
  std::vector<vtkSmartPointer<vtkBillboardTextActor3D>> m_labels;  // one per selected marker
  std::vector<Eigen::Index> m_labelMarkers;
  std::vector<std::string> m_labelTexts;
  double m_takeSize = 1.0;  // diagonal of the take's markers, fixed per take
  std::vector<Eigen::Index> m_drawnMarkers;  // point id -> marker
  int m_trailFrames = 50;
  double m_markerScale = 0.012;
  int m_upAxis = 2;
  std::vector<Eigen::Index> m_headReference;
  vtkNew<vtkPolyData> m_linkLines;
  vtkNew<vtkActor> m_linkActor;
  std::vector<std::pair<Eigen::Index, Eigen::Index>> m_links;
  bool m_linksVisible = false;
  bool m_labellingMode = false;
  LengthUnit m_displayUnit = LengthUnit::Millimetre;
  std::shared_ptr<const HeadMotion> m_headMotion;  // shared with the document's cache
  std::vector<bool> m_layoutKept;  // empty: no layout highlight
  std::vector<bool> m_layoutReference;  // empty or one per marker
  std::vector<QColor> m_labelColors;
  bool m_followHead = false;
  std::vector<Eigen::Index> m_followMarkers;
  QLabel* m_status = nullptr;
  std::optional<CameraState> m_framedCamera;  // as the last framing left it
};

} // namespace mocap::ui
