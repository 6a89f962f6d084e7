#include "views/video_view.h"

#include "document/reference_video.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

VideoView::VideoView(ReferenceVideo& video, QWidget* parent) : QWidget(parent), m_video(video)
{
  setMinimumSize(160, 90);
  connect(&video, &ReferenceVideo::frameShown, this, qOverload<>(&VideoView::update));
  connect(&video, &ReferenceVideo::changed, this, qOverload<>(&VideoView::update));
}

QRectF VideoView::imageRect() const
{
  const QImage& image = m_video.image();
  if (image.isNull())
    return {};
  const double fit = std::min(width() / static_cast<double>(image.width()), height() / static_cast<double>(image.height()));
  const QSizeF size(image.width() * fit * m_zoom, image.height() * fit * m_zoom);
  const QPointF centre = QPointF(width() / 2.0, height() / 2.0) + m_pan;
  return {centre - QPointF(size.width() / 2.0, size.height() / 2.0), size};
}

QString VideoView::caption() const
{
  if (!m_video.error().isEmpty())
    return m_video.error();
  if (!m_video.isOpen())
    return tr("No reference video");
  const std::optional<Eigen::Index> wanted = m_video.wantedFrame();
  if (!wanted)
    return tr("No video at this frame");
  const QString text =
      tr("video frame %1 · %2 s").arg(static_cast<qlonglong>(*wanted)).arg(m_video.timeOf(*wanted), 0, 'f', 3);
  return m_video.heldFrame() ? tr("%1 · held").arg(text) : text;
}

void VideoView::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  painter.fillRect(rect(), QColor(20, 20, 22));
  const std::optional<Eigen::Index> wanted = m_video.wantedFrame();
  if (wanted && !m_video.image().isNull()) {
    painter.setRenderHint(QPainter::SmoothPixmapTransform, m_zoom < 2.0);
    painter.drawImage(imageRect(), m_video.image());
  }
  const QString text = caption();
  painter.setPen(QColor(230, 230, 230));
  if (!wanted) {
    painter.drawText(rect().adjusted(8, 8, -8, -8), Qt::AlignCenter | Qt::TextWordWrap, text);
    return;
  }
  const QRectF box(6.0, 6.0, painter.fontMetrics().horizontalAdvance(text) + 10.0, 18.0);
  painter.fillRect(box, QColor(0, 0, 0, 160));
  painter.drawText(box, Qt::AlignCenter, text);
}

void VideoView::wheelEvent(QWheelEvent* event)
{
  const double factor = std::pow(1.15, event->angleDelta().y() / 120.0);
  const double zoom = std::clamp(m_zoom * factor, 1.0, 16.0);
  // Zoom around the cursor: the point under it stays put.
  const QPointF centre = QPointF(width() / 2.0, height() / 2.0) + m_pan;
  const QPointF cursor = event->position();
  m_pan += (cursor - centre) * (1.0 - zoom / m_zoom);
  m_zoom = zoom;
  if (m_zoom == 1.0)
    m_pan = {};
  update();
  event->accept();
}

void VideoView::mousePressEvent(QMouseEvent* event)
{
  m_dragStart = event->position();
  m_panStart = m_pan;
}

void VideoView::mouseMoveEvent(QMouseEvent* event)
{
  if (event->buttons() == Qt::NoButton || m_zoom == 1.0)
    return;
  m_pan = m_panStart + (event->position() - m_dragStart);
  update();
}

void VideoView::mouseDoubleClickEvent(QMouseEvent*)
{
  m_zoom = 1.0;
  m_pan = {};
  update();
}

} // namespace mocap::ui
