#pragma once

#include <QWidget>

#include "mocap/length_unit.h"
#include "mocap/sample_patch.h"

#include <Eigen/Core>

#include <array>
#include <optional>

namespace mocap::ui {

class TakeDocument;

/// x, y and z against frame for the selected markers, one strip per axis: samples coloured by
/// state, gaps of the first selected marker shaded, the current frame marked. Click sets the
/// current frame; Shift-drag selects a frame range (for range edits); the wheel zooms around
/// the cursor; right- or middle-drag pans; Ctrl+Home shows everything. Zoomed in far enough to
/// tell samples apart, dragging a sample of a selected marker up or down edits that coordinate
/// (one undoable command on release, previewed while dragging; Esc cancels). Each pixel column draws the min-max of its frames, so 20 000 frames cost the
/// same as the widget's width.
class CurveView final : public QWidget
{
  Q_OBJECT

public:
  explicit CurveView(TakeDocument& document, QWidget* parent = nullptr);

  /// Unit of the value labels (the take keeps its own units).
  void setDisplayUnit(LengthUnit unit);
  /// Visible frame range [first, last].
  void setVisibleRange(double first, double last);
  [[nodiscard]] double firstVisible() const { return m_first; }
  [[nodiscard]] double lastVisible() const { return m_last; }
  [[nodiscard]] QSize sizeHint() const override { return {800, 260}; }
  /// Where sample `frame` of `marker` on `axis` (0 x, 1 y, 2 z) was last drawn; nullopt before
  /// the first paint or when it is not drawn.
  [[nodiscard]] std::optional<QPointF> pointOf(Eigen::Index marker, Eigen::Index frame, int axis) const;

protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;

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
  [[nodiscard]] double frameAt(double x) const;
  [[nodiscard]] double xOf(double frame) const;
  [[nodiscard]] QRectF plotArea() const;
  void showAll();
  void paintStrip(class QPainter& painter, const QRectF& strip, int axis) const;
  void paintOverlay(QPainter& painter, const QRectF& strip, int axis, double lo, double hi) const;

  TakeDocument& m_document;
  double m_first = 0.0;
  double m_last = 1.0;
  QPointF m_panStart;
  Eigen::Index m_rangeAnchor = -1;
  double m_panFirst = 0.0;
  mutable std::array<StripScale, 3> m_scales{};
  LengthUnit m_displayUnit = LengthUnit::Millimetre;
  std::optional<Drag> m_drag;
};

} // namespace mocap::ui
