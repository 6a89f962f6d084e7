#pragma once

#include <QWidget>

#include <Eigen/Core>

namespace mocap::ui {

class TakeDocument;

/// x, y and z against frame for the selected markers, one strip per axis: samples coloured by
/// state, gaps of the first selected marker shaded, the current frame marked. Click sets the
/// current frame; Shift-drag selects a frame range (for range edits); the wheel zooms around
/// the cursor; right- or middle-drag pans; Ctrl+Home shows everything. Each pixel column draws the min-max of its frames, so 20 000 frames cost the
/// same as the widget's width.
class CurveView final : public QWidget
{
  Q_OBJECT

public:
  explicit CurveView(TakeDocument& document, QWidget* parent = nullptr);

  /// Visible frame range [first, last].
  void setVisibleRange(double first, double last);
  [[nodiscard]] double firstVisible() const { return m_first; }
  [[nodiscard]] double lastVisible() const { return m_last; }
  [[nodiscard]] QSize sizeHint() const override { return {800, 260}; }

protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;

private:
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
};

} // namespace mocap::ui
