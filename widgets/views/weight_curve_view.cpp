#include "views/weight_curve_view.h"

#include "document/blendshape_solve_model.h"
#include "document/take_document.h"
#include "views/display_units.h"
#include "views/selection_palette.h"

#include <QFileInfo>
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
  connect(&model, &BlendshapeSolveModel::selectedShapesChanged, this, qOverload<>(&WeightCurveView::update));
  for (const auto signal : {&BlendshapeSolveModel::resultChanged, &BlendshapeSolveModel::rigChanged})
    connect(&model, signal, this, &WeightCurveView::onCurvesChanged);
  connect(&model, &BlendshapeSolveModel::weightsEdited, this, &WeightCurveView::onCurvesChanged);
  connect(&model.retargetMap(), &RetargetMapModel::mapChanged, this, &WeightCurveView::onCurvesChanged);
  connect(&model.retargetMap(), &RetargetMapModel::gainChanged, this, &WeightCurveView::onCurvesChanged);
}

void WeightCurveView::onCurvesChanged()
{
  m_mappedStale = true;
  update();
}

void WeightCurveView::refreshMapped() const
{
  if (!m_mappedStale)
    return;
  m_mappedStale = false;
  m_mapped.reset();
  m_feeds.clear();
  m_low = 0.0;
  m_high = 1.0;
  const std::optional<RetargetMap>& map = m_model.retargetMap().map();
  if (!map || !m_model.hasResult() || !m_model.rig())
    return;
  const std::vector<std::string> names = m_model.rig()->shapeNames();
  try {
    m_mapped = applyRetargetMap(*map, names, m_model.weights());
  } catch (const std::exception&) {
    return;  // a map that does not fit the rig: the Retarget section says why; the shapes are drawn
  }
  for (const RetargetChannel& channel : map->channels) {
    std::vector<Eigen::Index> feeds;
    for (const RetargetSource& source : channel.sources)
      feeds.push_back(std::find(names.begin(), names.end(), source.shape) - names.begin());
    std::sort(feeds.begin(), feeds.end());
    feeds.erase(std::unique(feeds.begin(), feeds.end()), feeds.end());
    m_feeds.push_back(std::move(feeds));
  }
  // Gains and offsets may take a channel outside [0, 1]: the strip spans what is drawn.
  const Eigen::MatrixXd& values = m_mapped->weights;
  if (values.size() > 0 && values.allFinite()) {
    m_low = std::min(0.0, values.minCoeff());
    m_high = std::max(1.0, values.maxCoeff());
  }
}

bool WeightCurveView::showsMappedCurves() const
{
  refreshMapped();
  return m_mapped.has_value();
}

const Eigen::MatrixXd& WeightCurveView::curves() const
{
  refreshMapped();
  return m_mapped ? m_mapped->weights : m_model.weights();
}

QString WeightCurveView::curveName(Eigen::Index curve) const
{
  return showsMappedCurves() ? QString::fromStdString(m_mapped->names[static_cast<std::size_t>(curve)])
                             : m_model.shapeName(curve);
}

std::vector<Eigen::Index> WeightCurveView::highlightedCurves() const
{
  const std::vector<Eigen::Index>& selected = m_model.selectedShapes();
  if (!showsMappedCurves())
    return selected;
  std::vector<Eigen::Index> channels;
  for (std::size_t c = 0; c < m_feeds.size(); ++c)
    if (std::any_of(m_feeds[c].begin(), m_feeds[c].end(),
                    [&](Eigen::Index shape) { return std::binary_search(selected.begin(), selected.end(), shape); }))
      channels.push_back(static_cast<Eigen::Index>(c));
  return channels;
}

std::vector<Eigen::Index> WeightCurveView::shapesOfCurve(Eigen::Index curve) const
{
  return showsMappedCurves() ? m_feeds[static_cast<std::size_t>(curve)] : std::vector<Eigen::Index>{curve};
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
  const std::vector<Eigen::Index> highlighted = highlightedCurves();
  for (std::size_t i = 0; i < highlighted.size(); ++i) {
    labels.push_back(curveName(highlighted[i]));
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
  const Eigen::MatrixXd& weights = curves();
  paintValueTicks(painter, strip, m_low, m_high);
  painter.save();
  painter.setClipRect(strip.adjusted(0.0, -2.0, 0.0, 2.0));
  const std::vector<Eigen::Index> highlighted = highlightedCurves();
  for (Eigen::Index s = 0; s < weights.cols(); ++s)
    if (!std::binary_search(highlighted.begin(), highlighted.end(), s))
      paintSeries(painter, strip, weights.col(s), m_low, m_high, QPen(kFaint, 1.0));
  for (std::size_t i = 0; i < highlighted.size(); ++i)
    paintSeries(painter, strip, weights.col(highlighted[i]), m_low, m_high, QPen(selectionPaletteColor(i), 1.8));
  painter.restore();
  paintStripName(painter, strip,
                 showsMappedCurves()
                     ? tr("Weights through the map %1").arg(QFileInfo(m_model.retargetMap().name()).fileName())
                     : tr("Weights"));
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
  const Eigen::MatrixXd& values = curves();
  if (m_weightStrip.isNull() || shape < 0 || shape >= values.cols() || frame < 0 || frame >= values.rows())
    return std::nullopt;
  const double w = values(frame, shape);
  return QPointF(xOf(static_cast<double>(frame)),
                 m_weightStrip.bottom() - (w - m_low) / (m_high - m_low) * m_weightStrip.height());
}

Eigen::Index WeightCurveView::shapeAt(const QPointF& position) const
{
  if (m_weightStrip.isNull() || !m_weightStrip.adjusted(0.0, -kHitPixels, 0.0, kHitPixels).contains(position))
    return -1;
  const Eigen::Index frame = frameUnder(position.x());
  const std::vector<Eigen::Index> highlighted = highlightedCurves();
  Eigen::Index best = -1;
  double bestDistance = kHitPixels;
  // Highlighted curves win ties: they are drawn on top.
  for (int pass = 0; pass < 2; ++pass)
    for (Eigen::Index s = 0; s < curves().cols(); ++s) {
      if (std::binary_search(highlighted.begin(), highlighted.end(), s) != (pass == 0))
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
      .arg(curveName(shape))
      .arg(static_cast<qlonglong>(document().take().firstFrame() + frame))
      .arg(curves()(frame, shape), 0, 'f', 3);
}

bool WeightCurveView::pressItem(const QPointF& position)
{
  const Eigen::Index curve = shapeAt(position);
  if (curve < 0)
    return false;
  const std::vector<Eigen::Index> shapes = shapesOfCurve(curve);
  if (shapes.empty())
    return false;  // a channel holding its offset: no shape to select
  std::vector<Eigen::Index> selected = m_model.selectedShapes();
  if (QGuiApplication::keyboardModifiers() & Qt::ControlModifier) {
    // Ctrl: the curve's shapes leave the selection when all were in it, else join it.
    const bool all = std::all_of(shapes.begin(), shapes.end(), [&](Eigen::Index shape) {
      return std::find(selected.begin(), selected.end(), shape) != selected.end();
    });
    for (const Eigen::Index shape : shapes) {
      const auto it = std::find(selected.begin(), selected.end(), shape);
      if (all)
        selected.erase(it);
      else if (it == selected.end())
        selected.push_back(shape);
    }
  } else {
    selected = shapes;
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
