#include "views/curve_view.h"

#include "commands/apply_patches_command.h"
#include "document/take_document.h"
#include "views/display_units.h"
#include "views/sample_colors.h"

#include "mocap/gaps.h"
#include "mocap/sample_patch.h"

#include <QKeyEvent>
#include <QUndoStack>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace mocap::ui {

namespace {
constexpr double kLeftMargin = 56.0;
constexpr double kRightMargin = 8.0;
constexpr double kStripGap = 6.0;
const char* const kAxisNames[3] = {"X", "Y", "Z"};
} // namespace

CurveView::CurveView(TakeDocument& document, QWidget* parent) : QWidget(parent), m_document(document)
{
  setFocusPolicy(Qt::StrongFocus);
  setMinimumHeight(150);
  setAutoFillBackground(false);
  connect(&document, &TakeDocument::takeReset, this, &CurveView::showAll);
  connect(&document, &TakeDocument::samplesChanged, this, qOverload<>(&CurveView::update));
  connect(&document, &TakeDocument::selectionChanged, this, qOverload<>(&CurveView::update));
  connect(&document, &TakeDocument::currentFrameChanged, this, qOverload<>(&CurveView::update));
  connect(&document, &TakeDocument::rangeChanged, this, qOverload<>(&CurveView::update));
  connect(&document, &TakeDocument::previewChanged, this, qOverload<>(&CurveView::update));
  connect(&document, &TakeDocument::flagsChanged, this, qOverload<>(&CurveView::update));
  connect(&document, &TakeDocument::markersChanged, this, qOverload<>(&CurveView::update));
  showAll();
}

void CurveView::setDisplayUnit(LengthUnit unit)
{
  m_displayUnit = unit;
  update();
}

void CurveView::showAll()
{
  m_first = 0.0;
  m_last = std::max<double>(static_cast<double>(m_document.take().frameCount()) - 1.0, 1.0);
  update();
}

void CurveView::setVisibleRange(double first, double last)
{
  const double frames = std::max<double>(static_cast<double>(m_document.take().frameCount()) - 1.0, 1.0);
  const double span = std::clamp(last - first, 10.0, std::max(frames, 10.0));
  first = std::clamp(first, 0.0, std::max(frames - span, 0.0));
  m_first = first;
  m_last = first + span;
  update();
}

QRectF CurveView::plotArea() const
{
  return QRectF(kLeftMargin, 4.0, std::max(width() - kLeftMargin - kRightMargin, 10.0), std::max(height() - 20.0, 10.0));
}

double CurveView::xOf(double frame) const
{
  const QRectF area = plotArea();
  return area.left() + (frame - m_first) / (m_last - m_first) * area.width();
}

double CurveView::frameAt(double x) const
{
  const QRectF area = plotArea();
  return m_first + (x - area.left()) / area.width() * (m_last - m_first);
}

void CurveView::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  painter.fillRect(rect(), QColor(30, 32, 36));
  const Take& take = m_document.take();
  const QRectF area = plotArea();
  if (take.empty() || m_document.selection().empty()) {
    painter.setPen(QColor(160, 160, 160));
    painter.drawText(rect(), Qt::AlignCenter, tr("Select a marker to see its curves"));
    return;
  }
  const double stripHeight = (area.height() - 2 * kStripGap) / 3.0;
  for (int axis = 0; axis < 3; ++axis) {
    const QRectF strip(area.left(), area.top() + axis * (stripHeight + kStripGap), area.width(), stripHeight);
    paintStrip(painter, strip, axis);
  }
  if (m_document.hasRange()) {
    const double x0 = std::max(xOf(static_cast<double>(m_document.rangeFirst()) - 0.5), area.left());
    const double x1 = std::min(xOf(static_cast<double>(m_document.rangeLast()) + 0.5), area.right());
    if (x1 > x0)
      painter.fillRect(QRectF(x0, area.top(), x1 - x0, area.height()), QColor(90, 150, 255, 60));
  }
  // Current frame and the frame axis.
  painter.setPen(QPen(QColor(255, 255, 255, 160), 1.0));
  const double x = xOf(static_cast<double>(m_document.currentFrame()));
  painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
  painter.setPen(QColor(170, 170, 170));
  const auto firstLabel = static_cast<qlonglong>(take.firstFrame() + static_cast<std::int64_t>(std::lround(m_first)));
  const auto lastLabel = static_cast<qlonglong>(take.firstFrame() + static_cast<std::int64_t>(std::lround(m_last)));
  painter.drawText(QRectF(area.left(), area.bottom() + 2, 100, 14), Qt::AlignLeft, QString::number(firstLabel));
  painter.drawText(QRectF(area.right() - 100, area.bottom() + 2, 100, 14), Qt::AlignRight, QString::number(lastLabel));
}

void CurveView::paintStrip(QPainter& painter, const QRectF& strip, int axis) const
{
  const Take& take = m_document.take();
  const auto& selection = m_document.selection();
  const Eigen::Index first = std::max<Eigen::Index>(0, static_cast<Eigen::Index>(std::floor(m_first)));
  const Eigen::Index last = std::min<Eigen::Index>(take.frameCount() - 1, static_cast<Eigen::Index>(std::ceil(m_last)));
  painter.fillRect(strip, QColor(38, 41, 46));
  m_scales[static_cast<std::size_t>(axis)].drawn = false;

  // Shade the gaps of the first selected marker.
  for (const Gap& gap : findGaps(take.valid().col(selection.front()), selection.front())) {
    const double x0 = std::max(xOf(static_cast<double>(gap.firstFrame) - 0.5), strip.left());
    const double x1 = std::min(xOf(static_cast<double>(gap.firstFrame + gap.length) - 0.5), strip.right());
    if (x1 > x0)
      painter.fillRect(QRectF(x0, strip.top(), x1 - x0, strip.height()), QColor(150, 50, 50, 90));
  }

  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (Eigen::Index m : selection) {
    const auto values = take.trajectory(m).col(axis);
    for (Eigen::Index f = first; f <= last; ++f)
      if (take.isValid(f, m)) {
        lo = std::min(lo, values(f));
        hi = std::max(hi, values(f));
      }
  }
  painter.setPen(QColor(150, 150, 150));
  painter.drawText(QRectF(0, strip.top(), kLeftMargin - 6, 14), Qt::AlignRight,
                   QStringLiteral("%1 (%2)").arg(QLatin1String(kAxisNames[axis]), unitLabel(m_displayUnit)));
  if (!std::isfinite(lo))
    return;
  if (hi - lo < 1e-9) {
    lo -= 0.5;
    hi += 0.5;
  }
  painter.drawText(QRectF(0, strip.top() + 14, kLeftMargin - 6, 14), Qt::AlignRight,
                   formatLength(hi, take.units(), m_displayUnit));
  painter.drawText(QRectF(0, strip.bottom() - 14, kLeftMargin - 6, 14), Qt::AlignRight,
                   formatLength(lo, take.units(), m_displayUnit));
  auto yOf = [&](double v) { return strip.bottom() - (v - lo) / (hi - lo) * strip.height(); };
  m_scales[static_cast<std::size_t>(axis)] = {strip, lo, hi, true};

  painter.setRenderHint(QPainter::Antialiasing, false);
  const double framesPerPixel = (m_last - m_first) / strip.width();
  for (Eigen::Index m : selection) {
    const auto values = take.trajectory(m).col(axis);
    if (framesPerPixel > 1.0) {
      // Min-max envelope per pixel column, coloured by the column's "most edited" state.
      const int columns = static_cast<int>(strip.width());
      for (int c = 0; c < columns; ++c) {
        const auto f0 = std::max(first, static_cast<Eigen::Index>(std::floor(frameAt(strip.left() + c))));
        const auto f1 = std::min(last, static_cast<Eigen::Index>(std::floor(frameAt(strip.left() + c + 1))));
        double cmin = std::numeric_limits<double>::infinity(), cmax = -cmin;
        std::uint8_t state = 0;
        for (Eigen::Index f = f0; f <= f1; ++f)
          if (take.isValid(f, m)) {
            cmin = std::min(cmin, values(f));
            cmax = std::max(cmax, values(f));
            state = std::max(state, take.states()(f, m));
          }
        if (!std::isfinite(cmin))
          continue;
        painter.setPen(stateColor(static_cast<SampleState>(state)));
        const double x = strip.left() + c + 0.5;
        painter.drawLine(QPointF(x, yOf(cmin)), QPointF(x, yOf(cmax) - 0.5));
      }
    } else {
      painter.setRenderHint(QPainter::Antialiasing, true);
      for (Eigen::Index f = std::max<Eigen::Index>(first, 1); f <= last; ++f) {
        if (!take.isValid(f, m) || !take.isValid(f - 1, m))
          continue;
        painter.setPen(QPen(stateColor(take.state(f, m)), 1.5));
        painter.drawLine(QPointF(xOf(static_cast<double>(f - 1)), yOf(values(f - 1))),
                         QPointF(xOf(static_cast<double>(f)), yOf(values(f))));
      }
      painter.setRenderHint(QPainter::Antialiasing, false);
    }
  }
  paintOverlay(painter, strip, axis, lo, hi);
}

void CurveView::paintOverlay(QPainter& painter, const QRectF& strip, int axis, double lo, double hi) const
{
  const auto& selection = m_document.selection();
  auto yOf = [&](double v) { return strip.bottom() - (v - lo) / (hi - lo) * strip.height(); };
  auto selected = [&](Eigen::Index m) { return std::binary_search(selection.begin(), selection.end(), m); };
  painter.save();
  painter.setClipRect(strip);
  painter.setRenderHint(QPainter::Antialiasing, true);
  // The preview: what Apply would write, as bright dots over the take's curve.
  painter.setPen(Qt::NoPen);
  painter.setBrush(QColor(255, 255, 255, 200));
  for (const SamplePatch& patch : m_document.preview()) {
    if (!selected(patch.marker))
      continue;
    for (std::size_t i = 0; i < patch.frames.size(); ++i) {
      const auto f = static_cast<double>(patch.frames[i]);
      if (f < m_first || f > m_last || !patch.valid(static_cast<Eigen::Index>(i)))
        continue;
      painter.drawEllipse(QPointF(xOf(f), yOf(patch.positions(static_cast<Eigen::Index>(i), axis))), 1.6, 1.6);
    }
  }
  // Flags for review: red rings on the flagged samples.
  painter.setBrush(Qt::NoBrush);
  painter.setPen(QPen(colorScheme().flagged, 1.5));
  const Take& take = m_document.take();
  for (const auto& [marker, frame] : m_document.flags()) {
    if (!selected(marker) || static_cast<double>(frame) < m_first || static_cast<double>(frame) > m_last)
      continue;
    painter.drawEllipse(QPointF(xOf(static_cast<double>(frame)), yOf(take.trajectory(marker)(frame, axis))), 4.0, 4.0);
  }
  painter.restore();
}

std::optional<QPointF> CurveView::pointOf(Eigen::Index marker, Eigen::Index frame, int axis) const
{
  const Take& take = m_document.take();
  if (axis < 0 || axis > 2 || marker < 0 || marker >= take.markerCount() || frame < 0 ||
      frame >= take.frameCount() || !take.isValid(frame, marker))
    return std::nullopt;
  const StripScale& scale = m_scales[static_cast<std::size_t>(axis)];
  if (!scale.drawn)
    return std::nullopt;
  return QPointF(xOf(static_cast<double>(frame)), scale.yOf(take.trajectory(marker)(frame, axis)));
}

// A drag starts on a drawn sample of a selected marker, within a few pixels, and only when the
// view is zoomed in far enough that one pixel column does not stand for several frames.
bool CurveView::startDrag(const QPointF& position)
{
  constexpr double kGrabPixels = 6.0;
  if ((m_last - m_first) / plotArea().width() > 0.5)
    return false;
  const auto frame = static_cast<Eigen::Index>(std::lround(frameAt(position.x())));
  for (int axis = 0; axis < 3; ++axis) {
    if (!m_scales[static_cast<std::size_t>(axis)].rect.contains(position))
      continue;
    for (Eigen::Index m : m_document.selection()) {
      const auto point = pointOf(m, frame, axis);
      if (point && std::abs(point->y() - position.y()) <= kGrabPixels &&
          std::abs(point->x() - position.x()) <= kGrabPixels) {
        m_drag = Drag{m, frame, axis, point->y(), m_document.take().position(frame, m)};
        return true;
      }
    }
  }
  return false;
}

SamplePatch CurveView::dragPatch(const QPointF& position) const
{
  const StripScale& scale = m_scales[static_cast<std::size_t>(m_drag->axis)];
  Eigen::Vector3d moved = m_drag->original;
  moved(m_drag->axis) = scale.valueAt(position.y());
  return makePatch(m_drag->marker, {m_drag->frame}, moved.transpose(), SampleState::Edited);
}

void CurveView::updateDrag(const QPointF& position)
{
  m_document.setPreview({dragPatch(position)});
}

void CurveView::finishDrag(const std::optional<QPointF>& commitAt)
{
  if (!m_drag)
    return;
  // The patch comes from the release position, not from the preview, which a cleaning panel's
  // live preview may have replaced meanwhile.
  std::vector<SamplePatch> patches;
  if (commitAt)
    patches.push_back(dragPatch(*commitAt));
  const Drag drag = *std::exchange(m_drag, std::nullopt);
  m_document.clearPreview();
  if (patches.empty())
    return;
  const Take& take = m_document.take();
  m_document.undoStack()->push(new ApplyPatchesCommand(
      m_document, std::move(patches),
      tr("Move %1 %2 at frame %3")
          .arg(QString::fromStdString(take.label(drag.marker)), kAxisNames[drag.axis])
          .arg(static_cast<qlonglong>(take.firstFrame() + drag.frame))));
}

void CurveView::mousePressEvent(QMouseEvent* event)
{
  const auto frame = static_cast<Eigen::Index>(std::lround(frameAt(event->position().x())));
  if (event->button() == Qt::LeftButton && !(event->modifiers() & Qt::ShiftModifier) &&
      startDrag(event->position())) {
    m_document.setCurrentFrame(frame);
  } else if (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier)) {
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

void CurveView::mouseMoveEvent(QMouseEvent* event)
{
  const auto frame = static_cast<Eigen::Index>(std::lround(frameAt(event->position().x())));
  if (m_drag && (event->buttons() & Qt::LeftButton)) {
    updateDrag(event->position());
  } else if ((event->buttons() & Qt::LeftButton) && m_rangeAnchor >= 0) {
    m_document.setRange(std::min(m_rangeAnchor, frame), std::max(m_rangeAnchor, frame));
  } else if (event->buttons() & Qt::LeftButton) {
    m_document.setCurrentFrame(frame);
  } else if (event->buttons() & (Qt::RightButton | Qt::MiddleButton)) {
    const double span = m_last - m_first;
    const double shift = (event->position().x() - m_panStart.x()) / plotArea().width() * span;
    setVisibleRange(m_panFirst - shift, m_panFirst - shift + span);
  }
}

void CurveView::mouseReleaseEvent(QMouseEvent* event)
{
  m_rangeAnchor = -1;
  if (m_drag && event->button() == Qt::LeftButton)
    finishDrag(std::abs(event->position().y() - m_drag->startY) >= 1.0 ? std::optional(event->position())
                                                                        : std::nullopt);
}

void CurveView::wheelEvent(QWheelEvent* event)
{
  const double anchor = frameAt(event->position().x());
  const double factor = std::pow(0.85, event->angleDelta().y() / 120.0);
  setVisibleRange(anchor - (anchor - m_first) * factor, anchor + (m_last - anchor) * factor);
  event->accept();
}

void CurveView::keyPressEvent(QKeyEvent* event)
{
  if (event->key() == Qt::Key_Home && event->modifiers() & Qt::ControlModifier)
    showAll();
  else if (event->key() == Qt::Key_Escape && m_drag)
    finishDrag(std::nullopt);
  else
    QWidget::keyPressEvent(event);
}

} // namespace mocap::ui
