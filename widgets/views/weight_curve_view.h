#pragma once

#include "views/frame_strip_view.h"

#include "mocap/model/retarget_map.h"

#include <Eigen/Core>

#include <QString>

#include <optional>
#include <vector>

namespace mocap::ui {

class BlendshapeSolveModel;

/// The solved blendshape weights against frame (BlendshapeSolveModel): the top strip draws every
/// shape's curve faintly and the selected shapes' curves in their palette colours, named in the
/// legend; frames the solve held (too few markers) are shaded red. The bottom strip is the
/// per-frame marker residual (take units). A click on a curve selects its shape (Ctrl adds or
/// removes it); elsewhere the mouse works as every FrameStripView (current frame, Shift-drag
/// range for the weight edits, zoom, pan). When the Retarget section has a map loaded that fits
/// the rig, the top strip draws the map's channels instead (the curves Export Rig writes through
/// it, over their own range), named by channel: those a selected shape feeds in colour, and a
/// click on a channel selects the shapes it takes, so the edits act on them. Each pixel column
/// draws the min-max of its frames: O(visible frames × #curves + width) per paint, and
/// O(#frames · Σ #sources) to map the curves after a change.
class WeightCurveView final : public FrameStripView
{
  Q_OBJECT

public:
  WeightCurveView(TakeDocument& document, BlendshapeSolveModel& model, QWidget* parent = nullptr);

  [[nodiscard]] QSize sizeHint() const override { return {800, 260}; }
  /// True when the curves drawn are the retarget map's channels rather than the rig's shapes.
  [[nodiscard]] bool showsMappedCurves() const;
  /// The curve (a shape, or a channel when showsMappedCurves) passing within a few pixels of
  /// `position` at the frame under it (highlighted curves first), or −1. Valid after a paint.
  /// O(#curves).
  [[nodiscard]] Eigen::Index shapeAt(const QPointF& position) const;
  /// Where `frame` of curve `shape` (a channel when showsMappedCurves) is drawn (widget
  /// coordinates); nullopt before a paint.
  [[nodiscard]] std::optional<QPointF> pointOf(Eigen::Index shape, Eigen::Index frame) const;
  /// The hover read-out for `position` ("jawOpen · frame 1200 · 0.42"), empty off the curves.
  [[nodiscard]] QString readoutAt(const QPointF& position) const;

protected:
  void paintEvent(QPaintEvent* event) override;
  bool pressItem(const QPointF& position) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void leaveEvent(QEvent* event) override;

private:
  void paintWeights(QPainter& painter, const QRectF& strip) const;
  void paintResidual(QPainter& painter, const QRectF& strip) const;
  void paintHeld(QPainter& painter, const QRectF& strip) const;
  /// One curve of `values` (NaN: not drawn) in `strip` mapping [lo, hi] bottom to top.
  void paintSeries(QPainter& painter, const QRectF& strip, const Eigen::Ref<const Eigen::VectorXd>& values, double lo,
                   double hi, const QPen& pen) const;

  /// The curves drawn: the rig's weights, or the map's channels (mapped again when stale).
  [[nodiscard]] const Eigen::MatrixXd& curves() const;
  [[nodiscard]] QString curveName(Eigen::Index curve) const;
  /// The curves drawn in colour, in palette order: the selected shapes, or the channels they feed.
  [[nodiscard]] std::vector<Eigen::Index> highlightedCurves() const;
  /// The shapes a click on `curve` selects: itself, or the sources of the channel.
  [[nodiscard]] std::vector<Eigen::Index> shapesOfCurve(Eigen::Index curve) const;
  void refreshMapped() const;
  void onCurvesChanged();

  BlendshapeSolveModel& m_model;
  mutable std::optional<MappedWeights> m_mapped;           // the map's channels, when it fits the rig
  mutable std::vector<std::vector<Eigen::Index>> m_feeds;  // per channel, the shapes of its sources
  mutable bool m_mappedStale = true;
  mutable double m_low = 0.0, m_high = 1.0;  // the weight strip's value range
  mutable QRectF m_weightStrip;  // where the weights were drawn at the last paint
  std::optional<QPointF> m_hover;
};

} // namespace mocap::ui
