#pragma once

#include <QPointF>
#include <QWidget>

namespace mocap::ui {

class ReferenceVideo;

/// The reference video's frame for the current take frame, fitted to the widget (aspect kept);
/// the wheel zooms around the cursor, a drag pans, a double-click fits again. Says "No video at
/// this frame" outside the video and "No reference video" without one; the corner names the
/// video frame and its time. Painting costs one scaled image draw.
class VideoView final : public QWidget
{
  Q_OBJECT

public:
  explicit VideoView(ReferenceVideo& video, QWidget* parent = nullptr);

  [[nodiscard]] QSize sizeHint() const override { return {480, 270}; }
  [[nodiscard]] double zoom() const { return m_zoom; }
  /// The caption drawn over the frame ("video frame 42 · 1.400 s", or why there is none).
  [[nodiscard]] QString caption() const;

protected:
  void paintEvent(QPaintEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;

private:
  [[nodiscard]] QRectF imageRect() const;

  ReferenceVideo& m_video;
  double m_zoom = 1.0;
  QPointF m_pan;  // widget pixels the zoomed image is moved by
  QPointF m_dragStart;
  QPointF m_panStart;
};

} // namespace mocap::ui
