#pragma once

#include <QPointF>
#include <QRectF>
#include <QString>
#include <QWidget>

#include <Eigen/Core>

#include <vector>

class QColor;
class QPainter;

namespace mocap::ui {

class TakeDocument;

/// What every view of values against frame shares (the marker curves, the blendshape weights):
/// the visible frame range and its mapping to pixels, the frame and time ticks along the bottom,
/// the selected frame range shaded, the current frame marked, and the mouse: click sets the
/// current frame, Shift-drag selects a frame range (TakeDocument::setRange, for range edits), the
/// wheel zooms around the cursor, right- or middle-drag pans, Ctrl+Home shows everything. Setting
/// the current frame outside the visible range centres it (the zoom is kept). A subclass paints
/// its strips inside plotArea() and may take a press first (pressItem).
class FrameStripView : public QWidget
{
  Q_OBJECT

public:
  explicit FrameStripView(TakeDocument& document, QWidget* parent = nullptr);

  /// Visible frame range [first, last] (at least 10 frames, inside the take).
  void setVisibleRange(double first, double last);
  [[nodiscard]] double firstVisible() const { return m_first; }
  [[nodiscard]] double lastVisible() const { return m_last; }

protected:
  static constexpr double kLeftMargin = 60.0;
  static constexpr double kRightMargin = 8.0;
  static constexpr double kTopMargin = 20.0;     // the legend row
  static constexpr double kBottomMargin = 30.0;  // frame and time tick labels
  static constexpr double kStripGap = 6.0;

  [[nodiscard]] TakeDocument& document() const { return m_document; }
  [[nodiscard]] QRectF plotArea() const;
  [[nodiscard]] double xOf(double frame) const;
  [[nodiscard]] double frameAt(double x) const;
  /// The frame under widget x, rounded and clamped to the take.
  [[nodiscard]] Eigen::Index frameUnder(double x) const;
  /// `count` strips stacked in plotArea() with kStripGap between them, top to bottom.
  [[nodiscard]] std::vector<QRectF> strips(int count) const;
  void showAll();
  /// Centres `frame` when it lies outside the visible range.
  void follow(Eigen::Index frame);

  /// The selected range shaded, the current frame's line and the frame/time ticks. O(width).
  void paintFrameOverlay(QPainter& painter) const;
  /// Value grid lines and labels for a strip showing [lo, hi] (in the unit the labels show) from
  /// its bottom to its top. O(strip height).
  void paintValueTicks(QPainter& painter, const QRectF& strip, double lo, double hi) const;
  /// Left of the legend row: a swatch and label per entry, as many as fit before `limit` (x),
  /// then "+N more". O(#entries).
  void paintSwatchLegend(QPainter& painter, const std::vector<QString>& labels, const std::vector<QColor>& colors,
                         double limit) const;
  /// A strip's name on a dark plate at its top-left corner (readable over a curve).
  void paintStripName(QPainter& painter, const QRectF& strip, const QString& name) const;

  /// A left press the subclass handles itself (true: consumed; the current frame still moves
  /// there). Called before the range and frame handling. The default takes none.
  virtual bool pressItem(const QPointF& position);

  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;

private:
  TakeDocument& m_document;
  double m_first = 0.0;
  double m_last = 1.0;
  QPointF m_panStart;
  double m_panFirst = 0.0;
  Eigen::Index m_rangeAnchor = -1;
};

} // namespace mocap::ui
