#include "views/frame_strip_view.h"

#include "document/take_document.h"
#include "views/axis_ticks.h"

#include <QFontMetricsF>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

namespace {
const QColor kGrid(255, 255, 255, 26);
const QColor kTickText(150, 150, 150);
} // namespace

FrameStripView::FrameStripView(TakeDocument& document, QWidget* parent) : QWidget(parent), m_document(document)
{
  setFocusPolicy(Qt::StrongFocus);
  setAutoFillBackground(false);
  connect(&document, &TakeDocument::takeReset, this, &FrameStripView::showAll);
  connect(&document, &TakeDocument::currentFrameChanged, this, &FrameStripView::follow);
  connect(&document, &TakeDocument::rangeChanged, this, qOverload<>(&FrameStripView::update));
  showAll();
}

void FrameStripView::showAll()
{
  m_first = 0.0;
  m_last = std::max<double>(static_cast<double>(m_document.take().frameCount()) - 1.0, 1.0);
  update();
}

void FrameStripView::setVisibleRange(double first, double last)
{
  const double frames = std::max<double>(static_cast<double>(m_document.take().frameCount()) - 1.0, 1.0);
  const double span = std::clamp(last - first, 10.0, std::max(frames, 10.0));
  first = std::clamp(first, 0.0, std::max(frames - span, 0.0));
  m_first = first;
  m_last = first + span;
  update();
}

void FrameStripView::follow(Eigen::Index frame)
{
  const auto f = static_cast<double>(frame);
  if (f < m_first || f > m_last) {
    const double span = m_last - m_first;
    setVisibleRange(f - span / 2.0, f + span / 2.0);
  }
  update();
}

QRectF FrameStripView::plotArea() const
{
  return QRectF(kLeftMargin, kTopMargin, std::max(width() - kLeftMargin - kRightMargin, 10.0),
                std::max(height() - kTopMargin - kBottomMargin, 10.0));
}

double FrameStripView::xOf(double frame) const
{
  const QRectF area = plotArea();
  return area.left() + (frame - m_first) / (m_last - m_first) * area.width();
}

double FrameStripView::frameAt(double x) const
{
  const QRectF area = plotArea();
  return m_first + (x - area.left()) / area.width() * (m_last - m_first);
}

Eigen::Index FrameStripView::frameUnder(double x) const
{
  const Eigen::Index last = std::max<Eigen::Index>(m_document.take().frameCount() - 1, 0);
  return std::clamp<Eigen::Index>(static_cast<Eigen::Index>(std::lround(frameAt(x))), 0, last);
}

std::vector<QRectF> FrameStripView::strips(int count) const
{
  const QRectF area = plotArea();
  const double height = (area.height() - (count - 1) * kStripGap) / count;
  std::vector<QRectF> out;
  for (int i = 0; i < count; ++i)
    out.emplace_back(area.left(), area.top() + i * (height + kStripGap), area.width(), height);
  return out;
}

void FrameStripView::paintFrameOverlay(QPainter& painter) const
{
  const Take& take = m_document.take();
  const QRectF area = plotArea();
  if (m_document.hasRange()) {
    const double x0 = std::max(xOf(static_cast<double>(m_document.rangeFirst()) - 0.5), area.left());
    const double x1 = std::min(xOf(static_cast<double>(m_document.rangeLast()) + 0.5), area.right());
    if (x1 > x0)
      painter.fillRect(QRectF(x0, area.top(), x1 - x0, area.height()), QColor(90, 150, 255, 60));
  }
  const double current = xOf(static_cast<double>(m_document.currentFrame()));
  if (current >= area.left() && current <= area.right()) {
    painter.setPen(QPen(QColor(255, 255, 255, 160), 1.0));
    painter.drawLine(QPointF(current, area.top()), QPointF(current, area.bottom()));
  }

  const QFontMetricsF metrics(painter.font());
  const double widest = metrics.horizontalAdvance(QString::number(take.firstFrame() + take.frameCount())) + 16.0;
  const int count = std::max(2, static_cast<int>(area.width() / widest));
  // Frames as the file numbers them; the step is a whole number of frames.
  const double offset = static_cast<double>(take.firstFrame());
  const AxisTicks frames = niceTicks(m_first + offset, m_last + offset, count);
  const double step = std::max(1.0, frames.step);
  for (double label = std::ceil((m_first + offset) / step) * step; label <= m_last + offset + 1e-9; label += step) {
    const double x = xOf(label - offset);
    painter.setPen(kGrid);
    painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
    painter.setPen(kTickText);
    painter.drawLine(QPointF(x, area.bottom()), QPointF(x, area.bottom() + 3.0));
    painter.drawText(QRectF(x - widest / 2.0, area.bottom() + 2.0, widest, 13.0), Qt::AlignHCenter | Qt::AlignTop,
                     QString::number(static_cast<qlonglong>(std::llround(label))));
  }
  // Seconds from the first frame, on their own nice ticks below the frame numbers.
  const double rate = take.frameRate();
  const AxisTicks seconds = niceTicks(m_first / rate, m_last / rate, std::max(2, count));
  painter.setPen(QColor(120, 120, 120));
  for (const double t : seconds.values) {
    const double x = xOf(t * rate);
    painter.drawText(QRectF(x - widest / 2.0, area.bottom() + 15.0, widest, 13.0), Qt::AlignHCenter | Qt::AlignTop,
                     tr("%1 s").arg(t, 0, 'f', seconds.decimals));
  }
}

void FrameStripView::paintValueTicks(QPainter& painter, const QRectF& strip, double lo, double hi) const
{
  const AxisTicks ticks = niceTicks(lo, hi, std::max(4, static_cast<int>(strip.height() / 16.0)));
  painter.setRenderHint(QPainter::Antialiasing, false);
  for (const double v : ticks.values) {
    const double y = strip.bottom() - (v - lo) / (hi - lo) * strip.height();
    painter.setPen(kGrid);
    painter.drawLine(QPointF(strip.left(), y), QPointF(strip.right(), y));
    painter.setPen(kTickText);
    painter.drawLine(QPointF(strip.left() - 3.0, y), QPointF(strip.left(), y));
    painter.drawText(QRectF(0.0, y - 7.0, kLeftMargin - 6.0, 14.0), Qt::AlignRight | Qt::AlignVCenter,
                     QString::number(v, 'f', ticks.decimals));
  }
}

void FrameStripView::paintSwatchLegend(QPainter& painter, const std::vector<QString>& labels,
                                       const std::vector<QColor>& colors, double limit) const
{
  const QFontMetricsF metrics(painter.font());
  const double y = 3.0, h = 14.0;
  double x = kLeftMargin;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const double w = 16.0 + metrics.horizontalAdvance(labels[i]) + 12.0;
    const QString more = tr("+%1 more").arg(labels.size() - i);
    if (x + w > limit - (i + 1 < labels.size() ? metrics.horizontalAdvance(more) : 0.0)) {
      painter.setPen(kTickText);
      painter.drawText(QRectF(x, y, limit - x + 80.0, h), Qt::AlignLeft | Qt::AlignVCenter, more);
      break;
    }
    painter.fillRect(QRectF(x, y + 3.0, 11.0, h - 6.0), colors[i]);
    painter.setPen(QColor(215, 215, 215));
    painter.drawText(QRectF(x + 15.0, y, w, h), Qt::AlignLeft | Qt::AlignVCenter, labels[i]);
    x += w;
  }
}

void FrameStripView::paintStripName(QPainter& painter, const QRectF& strip, const QString& name) const
{
  const QRectF plate(strip.left() + 2.0, strip.top() + 2.0, QFontMetricsF(painter.font()).horizontalAdvance(name) + 8.0,
                     15.0);
  painter.fillRect(plate, QColor(30, 32, 36, 200));
  painter.setPen(QColor(190, 190, 190));
  painter.drawText(plate, Qt::AlignCenter, name);
}

bool FrameStripView::pressItem(const QPointF&)
{
  return false;
}

void FrameStripView::mousePressEvent(QMouseEvent* event)
{
  const Eigen::Index frame = frameUnder(event->position().x());
  const bool shift = (event->modifiers() & Qt::ShiftModifier) != 0;
  if (event->button() == Qt::LeftButton && !shift && pressItem(event->position())) {
    m_document.setCurrentFrame(frame);
  } else if (event->button() == Qt::LeftButton && shift) {
    m_rangeAnchor = frame;
    m_document.setRange(frame, frame);
  } else if (event->button() == Qt::LeftButton) {
    m_rangeAnchor = -1;
    m_document.clearRange();
    m_document.setCurrentFrame(frame);
  } else {
    m_panStart = event->position();
    m_panFirst = m_first;
  }
}

void FrameStripView::mouseMoveEvent(QMouseEvent* event)
{
  const Eigen::Index frame = frameUnder(event->position().x());
  if ((event->buttons() & Qt::LeftButton) && m_rangeAnchor >= 0) {
    m_document.setRange(std::min(m_rangeAnchor, frame), std::max(m_rangeAnchor, frame));
  } else if (event->buttons() & Qt::LeftButton) {
    m_document.setCurrentFrame(frame);
  } else if (event->buttons() & (Qt::RightButton | Qt::MiddleButton)) {
    const double span = m_last - m_first;
    const double shift = (event->position().x() - m_panStart.x()) / plotArea().width() * span;
    setVisibleRange(m_panFirst - shift, m_panFirst - shift + span);
  }
}

void FrameStripView::mouseReleaseEvent(QMouseEvent*)
{
  m_rangeAnchor = -1;
}

void FrameStripView::wheelEvent(QWheelEvent* event)
{
  const double anchor = frameAt(event->position().x());
  const double factor = std::pow(0.85, event->angleDelta().y() / 120.0);
  setVisibleRange(anchor - (anchor - m_first) * factor, anchor + (m_last - anchor) * factor);
  event->accept();
}

void FrameStripView::keyPressEvent(QKeyEvent* event)
{
  if (event->key() == Qt::Key_Home && (event->modifiers() & Qt::ControlModifier))
    showAll();
  else
    QWidget::keyPressEvent(event);
}

} // namespace mocap::ui
