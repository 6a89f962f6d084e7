#pragma once

#include "views/frame_strip_view.h"

#include <Eigen/Core>

#include <QString>

#include <optional>

namespace mocap::ui {

class BlendshapeSolveModel;

/// The solved blendshape weights against frame (BlendshapeSolveModel): the top strip draws every
/// shape's curve faintly and the selected shapes' curves in their palette colours, named in the
/// legend; frames the solve held (too few markers) are shaded red. The bottom strip is the
/// per-frame marker residual (take units). A click on a curve selects its shape (Ctrl adds or
/// removes it); elsewhere the mouse works as every FrameStripView (current frame, Shift-drag
/// range for the weight edits, zoom, pan). Each pixel column draws the min-max of its frames:
/// O(visible frames × #shapes + width) per paint.
class WeightCurveView final : public FrameStripView
{
  Q_OBJECT

public:
  WeightCurveView(TakeDocument& document, BlendshapeSolveModel& model, QWidget* parent = nullptr);

  [[nodiscard]] QSize sizeHint() const override { return {800, 260}; }
  /// The shape whose curve passes within a few pixels of `position` at the frame under it
  /// (selected shapes first), or −1. Valid after a paint. O(#shapes).
  [[nodiscard]] Eigen::Index shapeAt(const QPointF& position) const;
  /// Where weight `frame` of `shape` is drawn (widget coordinates); nullopt before a paint.
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

  BlendshapeSolveModel& m_model;
  mutable QRectF m_weightStrip;  // where the weights were drawn at the last paint
  std::optional<QPointF> m_hover;
};

} // namespace mocap::ui
