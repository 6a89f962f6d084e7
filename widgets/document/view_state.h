#pragma once

#include "document/color_scheme.h"

#include "mocap/base/length_unit.h"

#include <Eigen/Core>

#include <QObject>

#include <vector>

namespace mocap::ui {

struct StudioOptions;

/// How the open session is shown, beside what it holds: the 3D view's up axis, marker size,
/// trails, links and head follow, the display unit of every read-out, the colours, the layout
/// highlight and requests to frame the camera. The session owns one; views observe it (a view
/// redraws on its signals) instead of being told by the window, and followOptions() keeps it
/// on the user's remembered options. Each setter emits its signal only on a change (the layout
/// highlight on every call). O(1) each, the highlight O(#markers).
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
  void followHeadChanged(bool on);
  void displayUnitChanged(mocap::LengthUnit unit);
  void colorsChanged();
  void layoutHighlightChanged();
  void cameraResetRequested();

private:
  int m_upAxis = 2;
  int m_trailFrames = 50;
  double m_markerScale = 0.012;
  bool m_linksVisible = false;
  bool m_followHead = false;
  LengthUnit m_displayUnit = LengthUnit::Millimetre;
  ColorScheme m_colors;
  std::vector<bool> m_layoutKept;
  std::vector<bool> m_layoutReference;
};

} // namespace mocap::ui
