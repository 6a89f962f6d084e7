#include "views/layout_error_plot.h"

#include "views/axis_ticks.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

namespace {

constexpr double kLeft = 62.0;    // room for the y tick labels
constexpr double kRight = 14.0;
constexpr double kTop = 44.0;     // the legend, then the upper plot's title
constexpr double kBottom = 30.0;  // the x tick labels and axis title
constexpr double kGap = 26.0;     // between the plots: the lower plot's title

QColor curveColor(LayoutErrorPlot::Curve curve)
{
  switch (curve) {
  case LayoutErrorPlot::Curve::Pfa:
    return {40, 110, 220};
  case LayoutErrorPlot::Curve::Greedy:
    return {230, 120, 30};
  case LayoutErrorPlot::Curve::Random:
    break;
  }
  return {130, 130, 130};
}

constexpr std::array<LayoutErrorPlot::Curve, 3> kCurves = {
    LayoutErrorPlot::Curve::Pfa, LayoutErrorPlot::Curve::Greedy, LayoutErrorPlot::Curve::Random};

std::size_t index(LayoutErrorPlot::Measure measure)
{
  return static_cast<std::size_t>(measure);
}

std::size_t index(LayoutErrorPlot::Curve curve)
{
  return static_cast<std::size_t>(curve);
}

} // namespace

LayoutErrorPlot::LayoutErrorPlot(QWidget* parent) : QWidget(parent)
{
  setFocusPolicy(Qt::StrongFocus);
  setBackgroundRole(QPalette::Base);
  setAutoFillBackground(true);
  setToolTip(tr("Click a marker count (or use ←/→) to show its layout"));
}

void LayoutErrorPlot::setPlan(const LayoutPlan& plan, const PlanRigErrors* rig)
{
  m_hasRig = rig != nullptr;
  m_rows.clear();
  m_selectable.clear();
  for (const LayoutSize& entry : plan.sizes) {
    Row row;
    row.markers = entry.markerCount;
    const auto put = [&](Curve curve, const std::optional<ScoredLayout>& layout) {
      if (layout) {
        row.value[index(Measure::ReconstructionRmse)][index(curve)] = layout->reconstructionRmse;
        row.value[index(Measure::BlendshapeMse)][index(curve)] = layout->blendshapeError;
      }
    };
    put(Curve::Pfa, entry.pfa);
    put(Curve::Greedy, entry.greedy);
    if (entry.randomCount > 0) {
      row.value[index(Measure::ReconstructionRmse)][index(Curve::Random)] = entry.randomReconstructionRmse;
      row.value[index(Measure::BlendshapeMse)][index(Curve::Random)] = entry.randomBlendshapeError;
    }
    if (const LayoutSizeRigErrors* judged = rig ? rig->size(entry.markerCount) : nullptr) {
      auto& values = row.value[index(Measure::RigWeightMse)];
      if (judged->pfa && judged->pfa->judged())
        values[index(Curve::Pfa)] = judged->pfa->mse;
      if (judged->greedy && judged->greedy->judged())
        values[index(Curve::Greedy)] = judged->greedy->mse;
      if (judged->randomCount > 0 && std::isfinite(judged->randomMse))
        values[index(Curve::Random)] = judged->randomMse;
    }
    m_rows.push_back(row);
    if (entry.layout(plan.method))
      m_selectable.push_back(entry.markerCount);
  }
  m_recommended = plan.recommendedSize;
  const bool recommendedSelectable =
      std::find(m_selectable.begin(), m_selectable.end(), m_recommended) != m_selectable.end();
  m_selected = recommendedSelectable ? m_recommended : (m_selectable.empty() ? 0 : m_selectable.back());
  update();
}

void LayoutErrorPlot::clear()
{
  m_hasRig = false;
  m_rows.clear();
  m_selectable.clear();
  m_recommended = 0;
  m_selected = 0;
  update();
}

bool LayoutErrorPlot::setSelectedSize(Eigen::Index size)
{
  if (std::find(m_selectable.begin(), m_selectable.end(), size) == m_selectable.end())
    return false;
  if (size != m_selected) {
    m_selected = size;
    update();
    emit sizeSelected(size);
  }
  return true;
}

QRectF LayoutErrorPlot::plotArea(Measure measure) const
{
  const double plots = m_hasRig ? 3.0 : 2.0;
  const double height =
      std::max(10.0, (static_cast<double>(this->height()) - kTop - kBottom - (plots - 1.0) * kGap) / plots);
  const double width = std::max(10.0, static_cast<double>(this->width()) - kLeft - kRight);
  const double top = kTop + static_cast<double>(index(measure)) * (height + kGap);
  return {kLeft, top, width, height};
}

double LayoutErrorPlot::xOf(Eigen::Index size) const
{
  if (m_rows.empty())
    return kLeft;
  // Half a step of room on either side, so the end points are not on the frame.
  const double lo = static_cast<double>(m_rows.front().markers) - 0.5;
  const double hi = static_cast<double>(m_rows.back().markers) + 0.5;
  const QRectF area = plotArea(Measure::ReconstructionRmse);
  return area.left() + (static_cast<double>(size) - lo) / (hi - lo) * area.width();
}

double LayoutErrorPlot::maxValue(Measure measure) const
{
  double top = 0.0;
  for (const Row& row : m_rows)
    for (const auto& value : row.value[index(measure)])
      if (value && std::isfinite(*value))
        top = std::max(top, *value);
  return top > 0.0 ? top * 1.08 : 1.0;
}

double LayoutErrorPlot::yOf(Measure measure, double value) const
{
  const QRectF area = plotArea(measure);
  return area.bottom() - value / maxValue(measure) * area.height();
}

std::vector<QPointF> LayoutErrorPlot::points(Measure measure, Curve curve) const
{
  std::vector<QPointF> result;
  for (const Row& row : m_rows)
    if (const auto& value = row.value[index(measure)][index(curve)]; value && std::isfinite(*value))
      result.emplace_back(xOf(row.markers), yOf(measure, *value));
  return result;
}

void LayoutErrorPlot::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  if (m_rows.empty()) {
    painter.setPen(palette().color(QPalette::PlaceholderText));
    painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
                     tr("Run the plan to see the error for each marker count."));
    return;
  }
  paintLegend(painter);
  paintPlot(painter, Measure::ReconstructionRmse);
  paintPlot(painter, Measure::BlendshapeMse);
  if (m_hasRig)
    paintPlot(painter, Measure::RigWeightMse);
  painter.setPen(palette().color(QPalette::Text));
  painter.drawText(QRectF(kLeft, height() - 16.0, width() - kLeft - kRight, 16.0), Qt::AlignCenter,
                   tr("markers"));
}

void LayoutErrorPlot::paintLegend(QPainter& painter) const
{
  const QStringList names = {tr("PFA"), tr("Greedy"), tr("Random (mean)"), tr("Recommended")};
  const QFontMetricsF metrics(font());
  double x = kLeft;
  const double y = 12.0;
  for (int i = 0; i < names.size(); ++i) {
    QPen pen(i < 3 ? curveColor(kCurves[static_cast<std::size_t>(i)]) : palette().color(QPalette::Text), 2.0);
    if (i >= 2)
      pen.setStyle(Qt::DashLine);
    painter.setPen(pen);
    painter.drawLine(QPointF(x, y), QPointF(x + 18.0, y));
    painter.setPen(palette().color(QPalette::Text));
    painter.drawText(QPointF(x + 22.0, y + metrics.ascent() / 2.5), names[i]);
    x += 22.0 + metrics.horizontalAdvance(names[i]) + 14.0;
  }
}

void LayoutErrorPlot::paintPlot(QPainter& painter, Measure measure) const
{
  const QRectF area = plotArea(measure);
  const QColor text = palette().color(QPalette::Text);
  const QColor grid = palette().color(QPalette::Mid);
  const QFontMetricsF metrics(font());
  painter.setRenderHint(QPainter::Antialiasing, false);

  // Selected size as a band behind everything.
  if (m_selected > 0) {
    const double x = xOf(m_selected);
    const double half = std::max(3.0, (xOf(m_selected + 1) - x) / 2.0);
    QColor band = palette().color(QPalette::Highlight);
    band.setAlpha(60);
    painter.fillRect(QRectF(x - half, area.top(), 2.0 * half, area.height()), band);
  }

  // Horizontal grid and y labels.
  const double top = maxValue(measure);
  const double yStep = niceTickStep(top, 4);
  for (double v = 0.0; v <= top + 1e-12; v += yStep) {
    const double y = yOf(measure, v);
    painter.setPen(QPen(grid, 0.0, Qt::DotLine));
    painter.drawLine(QPointF(area.left(), y), QPointF(area.right(), y));
    painter.setPen(text);
    painter.drawText(QRectF(0.0, y - 8.0, kLeft - 6.0, 16.0), Qt::AlignRight | Qt::AlignVCenter,
                     QString::number(v, 'g', 3));
  }
  // x ticks: every size when they fit, else a nice spacing.
  const Eigen::Index first = m_rows.front().markers;
  const Eigen::Index last = m_rows.back().markers;
  const double widest = metrics.horizontalAdvance(QString::number(last)) + 8.0;
  const Eigen::Index xStep =
      std::max<Eigen::Index>(1, static_cast<Eigen::Index>(std::ceil(
                                    niceTickStep(static_cast<double>(last - first + 1),
                                             std::max(1, static_cast<int>(area.width() / widest))))));
  for (Eigen::Index s = (first + xStep - 1) / xStep * xStep; s <= last; s += xStep) {
    const double x = xOf(s);
    painter.setPen(grid);
    painter.drawLine(QPointF(x, area.bottom()), QPointF(x, area.bottom() + 4.0));
    painter.setPen(text);
    painter.drawText(QRectF(x - 20.0, area.bottom() + 3.0, 40.0, 14.0), Qt::AlignHCenter | Qt::AlignTop,
                     QString::number(s));
  }
  painter.setPen(text);
  painter.drawRect(area);
  painter.drawText(QRectF(area.left(), area.top() - 17.0, area.width(), 16.0), Qt::AlignLeft | Qt::AlignBottom,
                   measure == Measure::ReconstructionRmse ? tr("Marker reconstruction RMSE (mm)")
                   : measure == Measure::BlendshapeMse    ? tr("Blend-weight MSE (key poses)")
                                                          : tr("Rig-weight MSE (blendshape rig)"));

  // Recommended size.
  if (m_recommended > 0) {
    painter.setPen(QPen(text, 1.5, Qt::DashLine));
    painter.drawLine(QPointF(xOf(m_recommended), area.top()), QPointF(xOf(m_recommended), area.bottom()));
  }

  // The curves, each as a polyline through its points with a dot on every point.
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setClipRect(area.adjusted(-4.0, -4.0, 4.0, 4.0));
  for (const Curve curve : kCurves) {
    const std::vector<QPointF> line = points(measure, curve);
    QPen pen(curveColor(curve), 2.0);
    if (curve == Curve::Random)
      pen.setStyle(Qt::DashLine);
    painter.setPen(pen);
    painter.setBrush(Qt::NoBrush);
    painter.drawPolyline(line.data(), static_cast<int>(line.size()));
    painter.setBrush(curveColor(curve));
    painter.setPen(Qt::NoPen);
    for (const QPointF& p : line)
      painter.drawEllipse(p, 2.5, 2.5);
  }
  painter.setClipping(false);
  painter.setBrush(Qt::NoBrush);
}

void LayoutErrorPlot::mousePressEvent(QMouseEvent* event)
{
  if (event->button() != Qt::LeftButton || m_selectable.empty())
    return QWidget::mousePressEvent(event);
  const double x = event->position().x();
  const auto nearest = std::min_element(m_selectable.begin(), m_selectable.end(), [&](Eigen::Index a, Eigen::Index b) {
    return std::abs(xOf(a) - x) < std::abs(xOf(b) - x);
  });
  setSelectedSize(*nearest);
}

void LayoutErrorPlot::step(int direction)
{
  const auto it = std::find(m_selectable.begin(), m_selectable.end(), m_selected);
  if (it == m_selectable.end())
    return;
  const auto position = it - m_selectable.begin() + direction;
  if (position >= 0 && position < static_cast<std::ptrdiff_t>(m_selectable.size()))
    setSelectedSize(m_selectable[static_cast<std::size_t>(position)]);
}

void LayoutErrorPlot::keyPressEvent(QKeyEvent* event)
{
  if (event->key() == Qt::Key_Left)
    step(-1);
  else if (event->key() == Qt::Key_Right)
    step(1);
  else
    QWidget::keyPressEvent(event);
}

bool LayoutErrorPlot::event(QEvent* event)
{
  // ←/→ step frames as window shortcuts; with the focus here they step marker counts instead.
  if (event->type() == QEvent::ShortcutOverride) {
    const int key = static_cast<QKeyEvent*>(event)->key();
    if ((key == Qt::Key_Left || key == Qt::Key_Right) &&
        static_cast<QKeyEvent*>(event)->modifiers() == Qt::NoModifier) {
      event->accept();
      return true;
    }
  }
  return QWidget::event(event);
}

} // namespace mocap::ui
