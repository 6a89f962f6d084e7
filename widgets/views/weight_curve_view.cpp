#include "views/weight_curve_view.h"

#include "document/blendshape_solve_model.h"
#include "document/take_document.h"
#include "views/display_units.h"
#include "views/selection_palette.h"

#include <QGuiApplication>
#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mocap::ui {

namespace {
constexpr double kHitPixels = 5.0;  // how near a click must be to a curve to select its shape
const QColor kFaint(150, 150, 150, 70);
} // namespace

WeightCurveView::WeightCurveView(TakeDocument& document, BlendshapeSolveModel& model, QWidget* parent)
    : FrameStripView(document, parent), m_model(model)
{
  setMinimumHeight(150);
  setMouseTracking(true);  // the hover read-out
  for (const auto signal : {&BlendshapeSolveModel::resultChanged, &BlendshapeSolveModel::selectedShapesChanged,
                            &BlendshapeSolveModel::rigChanged})
    connect(&model, signal, this, qOverload<>(&WeightCurveView::update));
  connect(&model, &BlendshapeSolveModel::weightsEdited, this, qOverload<>(&WeightCurveView::update));
}

void WeightCurveView::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  painter.fillRect(rect(), QColor(30, 32, 36));
  m_weightStrip = QRectF();
  if (!m_model.hasResult()) {
    painter.setPen(QColor(160, 160, 160));
    painter.drawText(rect(), Qt::AlignCenter,
                     m_model.hasRig() ? tr("Solve the take to see its weights")
                                      : tr("Load a blendshape rig in the Blendshape Solve panel"));
    return;
  }
  const QRectF area = plotArea();
  const double residualHeight = std::round(area.height() * 0.28);
  const QRectF weights(area.left(), area.top(), area.width(), area.height() - residualHeight - kStripGap);
  const QRectF residual(area.left(), weights.bottom() + kStripGap, area.width(), residualHeight);
  paintWeights(painter, weights);
  paintResidual(painter, residual);
  paintFrameOverlay(painter);

  std::vector<QString> labels;
  std::vector<QColor> colors;
  const auto& selected = m_model.selectedShapes();
  for (std::size_t i = 0; i < selected.size(); ++i) {
    labels.push_back(m_model.shapeName(selected[i]));
    colors.push_back(selectionPaletteColor(i));
  }
  if (labels.empty()) {
    painter.setPen(QColor(150, 150, 150));
    painter.drawText(QRectF(kLeftMargin, 3.0, width() - kLeftMargin, 14.0), Qt::AlignLeft | Qt::AlignVCenter,
                     tr("Click a curve (or pick shapes in the panel) to select its shape"));
  }
  paintSwatchLegend(painter, labels, colors, width() - kRightMargin);
  const QString readout = m_hover ? readoutAt(*m_hover) : QString();
  if (!readout.isEmpty()) {
    const QRectF box(m_hover->x() + 12.0, m_hover->y() - 20.0, painter.fontMetrics().horizontalAdvance(readout) + 10.0,
                     17.0);
    painter.fillRect(box, QColor(20, 20, 24, 220));
    painter.setPen(QColor(230, 230, 230));
    painter.drawText(box, Qt::AlignCenter, readout);
  }
}

void WeightCurveView::paintHeld(QPainter& painter, const QRectF& strip) const
{
  const std::vector<bool>& held = m_model.result().held;
  for (std::size_t f = 0; f < held.size(); ++f) {
    if (!held[f])
      continue;
    std::size_t end = f;
    while (end + 1 < held.size() && held[end + 1])
      ++end;
    const double x0 = std::max(xOf(static_cast<double>(f) - 0.5), strip.left());
    const double x1 = std::min(xOf(static_cast<double>(end) + 0.5), strip.right());
    if (x1 > x0)
      painter.fillRect(QRectF(x0, strip.top(), std::max(x1 - x0, 1.0), strip.height()), QColor(220, 60, 60, 50));
    f = end;
  }
}

void WeightCurveView::paintWeights(QPainter& painter, const QRectF& strip) const
{
  painter.fillRect(strip, QColor(38, 41, 46));
  m_weightStrip = strip;
  paintHeld(painter, strip);
  paintValueTicks(painter, strip, 0.0, 1.0);
  painter.save();
  painter.setClipRect(strip.adjusted(0.0, -2.0, 0.0, 2.0));
  const Eigen::MatrixXd& weights = m_model.weights();
  const auto& selected = m_model.selectedShapes();
  for (Eigen::Index s = 0; s < weights.cols(); ++s)
    if (!std::binary_search(selected.begin(), selected.end(), s))
      paintSeries(painter, strip, weights.col(s), 0.0, 1.0, QPen(kFaint, 1.0));
  for (std::size_t i = 0; i < selected.size(); ++i)
    paintSeries(painter, strip, weights.col(selected[i]), 0.0, 1.0, QPen(selectionPaletteColor(i), 1.8));
  painter.restore();
  paintStripName(painter, strip, tr("Weights"));
}

void WeightCurveView::paintResidual(QPainter& painter, const QRectF& strip) const
{
  painter.fillRect(strip, QColor(38, 41, 46));
  const Eigen::VectorXd& residual = m_model.result().residual;
  double hi = 0.0;
  for (const double r : residual)
    if (std::isfinite(r))
      hi = std::max(hi, r);
  hi = hi > 0.0 ? hi * 1.05 : 1.0;
  paintValueTicks(painter, strip, 0.0, hi);
  painter.save();
  painter.setClipRect(strip);
  paintSeries(painter, strip, residual, 0.0, hi, QPen(QColor(230, 170, 90), 1.2));
  painter.restore();
  paintStripName(painter, strip, tr("Marker residual (%1)").arg(unitLabel(document().take().units())));
}

// Zoomed out, each pixel column draws its frames' min-max joined to the previous column; zoomed
// in, one segment per pair of neighbouring frames. NaN frames break the curve.
void WeightCurveView::paintSeries(QPainter& painter, const QRectF& strip,
                                  const Eigen::Ref<const Eigen::VectorXd>& values, double lo, double hi,
                                  const QPen& pen) const
{
  const auto yOf = [&](double v) { return strip.bottom() - (v - lo) / (hi - lo) * strip.height(); };
  const Eigen::Index last = values.size() - 1;
  const Eigen::Index first = std::max<Eigen::Index>(0, static_cast<Eigen::Index>(std::floor(firstVisible())));
  const Eigen::Index end = std::min<Eigen::Index>(last, static_cast<Eigen::Index>(std::ceil(lastVisible())));
  QVector<QLineF> lines;
  const double framesPerPixel = (lastVisible() - firstVisible()) / strip.width();
  if (framesPerPixel > 1.0) {
    double previous = std::numeric_limits<double>::quiet_NaN();
    for (int c = 0; c < static_cast<int>(strip.width()); ++c) {
      const auto f0 = std::max(first, static_cast<Eigen::Index>(std::floor(frameAt(strip.left() + c))));
      const auto f1 = std::min(end, static_cast<Eigen::Index>(std::floor(frameAt(strip.left() + c + 1))));
      double cmin = std::numeric_limits<double>::infinity(), cmax = -cmin;
      for (Eigen::Index f = f0; f <= f1; ++f)
        if (std::isfinite(values(f))) {
          cmin = std::min(cmin, values(f));
          cmax = std::max(cmax, values(f));
        }
      if (!std::isfinite(cmin)) {
        previous = std::numeric_limits<double>::quiet_NaN();
        continue;
      }
      if (std::isfinite(previous)) {  // joined to the previous column
        cmin = std::min(cmin, previous);
        cmax = std::max(cmax, previous);
      }
      previous = values(f1);
      const double x = strip.left() + c + 0.5;
      lines.push_back(QLineF(QPointF(x, yOf(cmin) + 0.5), QPointF(x, yOf(cmax) - 0.5)));
    }
  } else {
    for (Eigen::Index f = std::max<Eigen::Index>(first, 1); f <= end; ++f)
      if (std::isfinite(values(f - 1)) && std::isfinite(values(f)))
        lines.push_back(QLineF(QPointF(xOf(static_cast<double>(f - 1)), yOf(values(f - 1))),
                               QPointF(xOf(static_cast<double>(f)), yOf(values(f)))));
  }
  painter.setRenderHint(QPainter::Antialiasing, framesPerPixel <= 1.0);
  painter.setPen(pen);
  painter.drawLines(lines);
  painter.setRenderHint(QPainter::Antialiasing, false);
}

std::optional<QPointF> WeightCurveView::pointOf(Eigen::Index shape, Eigen::Index frame) const
{
  if (m_weightStrip.isNull() || shape < 0 || shape >= m_model.weights().cols() || frame < 0 ||
      frame >= m_model.weights().rows())
    return std::nullopt;
  const double w = m_model.weights()(frame, shape);
  return QPointF(xOf(static_cast<double>(frame)), m_weightStrip.bottom() - w * m_weightStrip.height());
}

Eigen::Index WeightCurveView::shapeAt(const QPointF& position) const
{
  if (m_weightStrip.isNull() || !m_weightStrip.adjusted(0.0, -kHitPixels, 0.0, kHitPixels).contains(position))
    return -1;
  const Eigen::Index frame = frameUnder(position.x());
  const auto& selected = m_model.selectedShapes();
  Eigen::Index best = -1;
  double bestDistance = kHitPixels;
  // Selected shapes win ties: they are drawn on top.
  for (int pass = 0; pass < 2; ++pass)
    for (Eigen::Index s = 0; s < m_model.weights().cols(); ++s) {
      if (std::binary_search(selected.begin(), selected.end(), s) != (pass == 0))
        continue;
      const std::optional<QPointF> point = pointOf(s, frame);
      const double distance = point ? std::abs(point->y() - position.y()) : kHitPixels;
      if (distance < bestDistance) {
        bestDistance = distance;
        best = s;
      }
    }
  return best;
}

QString WeightCurveView::readoutAt(const QPointF& position) const
{
  const Eigen::Index shape = shapeAt(position);
  if (shape < 0)
    return {};
  const Eigen::Index frame = frameUnder(position.x());
  return tr("%1 · frame %2 · %3")
      .arg(m_model.shapeName(shape))
      .arg(static_cast<qlonglong>(document().take().firstFrame() + frame))
      .arg(m_model.weights()(frame, shape), 0, 'f', 3);
}

bool WeightCurveView::pressItem(const QPointF& position)
{
  const Eigen::Index shape = shapeAt(position);
  if (shape < 0)
    return false;
  std::vector<Eigen::Index> selected = m_model.selectedShapes();
  if (QGuiApplication::keyboardModifiers() & Qt::ControlModifier) {
    const auto it = std::find(selected.begin(), selected.end(), shape);
    if (it != selected.end())
      selected.erase(it);
    else
      selected.push_back(shape);
  } else {
    selected = {shape};
  }
  m_model.setSelectedShapes(std::move(selected));
  return true;
}

void WeightCurveView::mouseMoveEvent(QMouseEvent* event)
{
  FrameStripView::mouseMoveEvent(event);
  m_hover = event->buttons() == Qt::NoButton ? std::optional(event->position()) : std::nullopt;
  update();
}

void WeightCurveView::leaveEvent(QEvent* event)
{
  m_hover.reset();
  update();
  FrameStripView::leaveEvent(event);
}

} // namespace mocap::ui
