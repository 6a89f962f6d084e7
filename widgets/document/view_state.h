#pragma once

#include "document/color_scheme.h"

#include "mocap/base/length_unit.h"

#include <Eigen/Core>

#include <QObject>

#include <vector>

namespace mocap::ui {

struct StudioOptions;

/// How the open session is shown, beside what it holds: the 3D view's up axis, marker size,
/// trails, links, head reference (the head-stabilized view) and head follow, the display unit of
/// every read-out, the colours, the layout highlight, the face mesh's look, whether and where the
/// posed rig is drawn, and requests to frame the camera. The session owns one; views observe it
/// (a view redraws on its signals) instead of being told by the window, and followOptions() keeps
/// it on the user's remembered options. Each setter emits its signal only on a change (the layout
/// highlight and the head reference on every call). O(1) each, the highlight O(#markers).
class ViewState final : public QObject
{
  Q_OBJECT

public:
  explicit ViewState(QObject* parent = nullptr);

  [[nodiscard]] int upAxis() const { return m_upAxis; }
  /// 1 = Y up, 2 = Z up (anything else: Z).
  void setUpAxis(int axis);
  [[nodiscard]] int trailFrames() const { return m_trailFrames; }
  /// ± frames of the selected markers' trails; 0: none.
  void setTrailFrames(int frames);
  [[nodiscard]] double markerScale() const { return m_markerScale; }
  /// Sphere radius as a fraction of the take's size.
  void setMarkerScale(double fraction);
  [[nodiscard]] bool linksVisible() const { return m_linksVisible; }
  void setLinksVisible(bool visible);
  /// The reference markers whose head frame the 3D view shows the take in (View ▸ Head-Stabilized
  /// View); empty: the lab frame. Announced on every call, as the layout highlight: after an edit the
  /// same indices may be other markers, and a view that dropped its copy must get them again.
  [[nodiscard]] const std::vector<Eigen::Index>& headReference() const { return m_headReference; }
  void setHeadReference(std::vector<Eigen::Index> markers);
  [[nodiscard]] bool followHead() const { return m_followHead; }
  void setFollowHead(bool on);
  [[nodiscard]] LengthUnit displayUnit() const { return m_displayUnit; }
  void setDisplayUnit(LengthUnit unit);
  [[nodiscard]] const ColorScheme& colors() const { return m_colors; }
  /// The colours every view draws with; also made the application's scheme (sample_colors.h),
  /// which the views read while drawing.
  void setColors(const ColorScheme& colors);
  /// The planned layout shown over the take (one flag per marker; empty: none), and the head
  /// reference markers it leaves out. Views check it fits their take (a flag per marker).
  [[nodiscard]] const std::vector<bool>& layoutKept() const { return m_layoutKept; }
  [[nodiscard]] const std::vector<bool>& layoutReference() const { return m_layoutReference; }
  void setLayoutHighlight(std::vector<bool> kept, std::vector<bool> reference);
  /// The face mesh layers' look, opacity 0–1 and edges (FaceMeshScene observes it; the Face Mesh
  /// dock sets it).
  [[nodiscard]] double meshOpacity() const { return m_meshOpacity; }
  void setMeshOpacity(double opacity);
  [[nodiscard]] bool meshEdges() const { return m_meshEdges; }
  void setMeshEdges(bool visible);
  /// The posed blendshape rig: drawn, and beside the markers rather than over them (BlendshapeScene
  /// observes it; the Blendshape Solve dock sets it).
  [[nodiscard]] bool rigShown() const { return m_rigShown; }
  void setRigShown(bool shown);
  [[nodiscard]] bool rigBeside() const { return m_rigBeside; }
  void setRigBeside(bool beside);
  /// Asks the views to frame what they draw (View ▸ Reset Camera, a face mesh or rig just shown).
  void resetCamera() { emit cameraResetRequested(); }

  /// Keeps this state on `options` (up axis, marker size, trails, links, follow, unit, colours)
  /// from now on, while this state lives.
  void followOptions(const StudioOptions& options);

signals:
  void upAxisChanged(int axis);
  void trailFramesChanged(int frames);
  void markerScaleChanged(double fraction);
  void linksVisibleChanged(bool visible);
  void headReferenceChanged();
  void followHeadChanged(bool on);
  void displayUnitChanged(mocap::LengthUnit unit);
  void colorsChanged();
  void layoutHighlightChanged();
  void meshLookChanged();
  void rigShownChanged(bool shown);
  void rigBesideChanged(bool beside);
  void cameraResetRequested();

private:
  int m_upAxis = 2;
  int m_trailFrames = 50;
  double m_markerScale = 0.012;
  bool m_linksVisible = false;
  std::vector<Eigen::Index> m_headReference;
  bool m_followHead = false;
  LengthUnit m_displayUnit = LengthUnit::Millimetre;
  ColorScheme m_colors;
  std::vector<bool> m_layoutKept;
  std::vector<bool> m_layoutReference;
  double m_meshOpacity = 0.6;  // MeshLayer's default
  bool m_meshEdges = false;
  bool m_rigShown = true;
  bool m_rigBeside = true;
};

} // namespace mocap::ui
