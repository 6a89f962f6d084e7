#pragma once

#include "views/frame_strip_view.h"

#include <QString>

#include "mocap/base/length_unit.h"
#include "mocap/model/sample_patch.h"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <utility>

namespace mocap::ui {

class TakeDocument;
class ViewState;

/// x, y and z against frame for the selected markers, one strip per axis. Each selected marker
/// has its own colour (selection_palette.h, shared with the 3D view) named in the legend above
/// the strips; samples that are not original (filled, smoothed, edited) get a halo in their
/// state's colour; each marker's gaps are shaded lightly in its colour. Value ticks and a grid
/// in the display unit, frame and time ticks along the bottom, the current frame marked, and
/// the live preview (TakeDocument::preview) drawn as a thick dashed line with dots, inside the
/// strip's value range. Hovering shows marker, frame and value. Frame range, ticks, zoom, pan
/// and range selection as every FrameStripView. Zoomed in far enough to tell samples apart,
/// dragging a sample of a selected marker up or down edits that coordinate (one undoable command
/// on release, previewed while dragging; Esc cancels). Each pixel column draws the min-max of its
/// frames, so painting costs O(visible frames × selected markers + width), whatever the zoom.
class CurveView final : public FrameStripView
{
  Q_OBJECT

public:
  explicit CurveView(TakeDocument& document, QWidget* parent = nullptr);

  /// Unit of the value labels (the take keeps its own units).
  void setDisplayUnit(LengthUnit unit);
  /// Follows `state`'s display unit and colours from now on.
  void observe(const ViewState& state);
  [[nodiscard]] QSize sizeHint() const override { return {800, 260}; }
  /// Where sample `frame` of `marker` on `axis` (0 x, 1 y, 2 z) was last drawn; nullopt before
  /// the first paint or when it is not drawn.
  [[nodiscard]] std::optional<QPointF> pointOf(Eigen::Index marker, Eigen::Index frame, int axis) const;
  /// The value range strip `axis` shows (take units, margins included): every visible valid
  /// sample of the selected markers and of the preview patches for them. nullopt when there is
  /// nothing to show. O(visible frames × selected markers + preview size).
  [[nodiscard]] std::optional<std::pair<double, double>> valueRange(int axis) const;
  /// The hover read-out for widget position `position` ("section3-1 · frame 1000 (8.325 s) ·
  /// Z 12.3 mm"): the selected marker drawn nearest in y at the frame under the cursor, in the
  /// strip under it; empty when none is. Valid after a paint. O(#selected).
  [[nodiscard]] QString readoutAt(const QPointF& position) const;

protected:
  void paintEvent(QPaintEvent* event) override;
  bool pressItem(const QPointF& position) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void leaveEvent(QEvent* event) override;

private:
  /// How a strip mapped values to pixels at the last paint.
  struct StripScale
  {
    QRectF rect;
    double lo = 0.0;
    double hi = 1.0;
    bool drawn = false;
    [[nodiscard]] double yOf(double v) const { return rect.bottom() - (v - lo) / (hi - lo) * rect.height(); }
    [[nodiscard]] double valueAt(double y) const { return lo + (rect.bottom() - y) / rect.height() * (hi - lo); }
  };
  /// The sample being dragged.
  struct Drag
  {
    Eigen::Index marker = -1;
    Eigen::Index frame = 0;
    int axis = 0;
    double startY = 0.0;
    Eigen::Vector3d original = Eigen::Vector3d::Zero();
  };

  bool startDrag(const QPointF& position);
  void updateDrag(const QPointF& position);
  void finishDrag(const std::optional<QPointF>& commitAt);
  [[nodiscard]] SamplePatch dragPatch(const QPointF& position) const;
  /// The marker, frame and axis readoutAt() describes.
  struct HoverSample
  {
    Eigen::Index marker = -1;
    Eigen::Index frame = 0;
    int axis = 0;
  };
  [[nodiscard]] std::optional<HoverSample> sampleAt(const QPointF& position) const;
  void paintStrip(class QPainter& painter, const QRectF& strip, int axis) const;
  void paintValueTicks(QPainter& painter, const QRectF& strip, double lo, double hi) const;
  void paintCurve(QPainter& painter, const QRectF& strip, Eigen::Index marker, int axis, const QColor& color) const;
  void paintPreview(QPainter& painter, const QRectF& strip, int axis) const;
  void paintFlags(QPainter& painter, const QRectF& strip, int axis) const;
  void paintLegend(QPainter& painter) const;
  void paintReadout(QPainter& painter) const;

  TakeDocument& m_document;
  mutable std::array<StripScale, 3> m_scales{};
  LengthUnit m_displayUnit = LengthUnit::Millimetre;
  std::optional<Drag> m_drag;
  std::optional<QPointF> m_hover;  // mouse position while it moves over the view unpressed
};

} // namespace mocap::ui
