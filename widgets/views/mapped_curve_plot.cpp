#include "views/mapped_curve_plot.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

namespace {

/// The min–max of each pixel column's frames, joined column to column.
void paintCurve(QPainter& painter, const QRectF& area, const Eigen::VectorXd& values, double lo, double hi,
                const QPen& pen)
{
  if (values.size() == 0)
    return;
  painter.setPen(pen);
  const auto yOf = [&](double v) { return area.bottom() - (v - lo) / (hi - lo) * area.height(); };
  const int columns = std::max(1, static_cast<int>(area.width()));
  const double framesPerColumn = static_cast<double>(values.size()) / columns;
  QPointF previous;
  bool havePrevious = false;
  for (int c = 0; c < columns; ++c) {
    const auto first = static_cast<Eigen::Index>(std::floor(c * framesPerColumn));
    const auto last = std::min<Eigen::Index>(values.size() - 1,
                                             std::max(first, static_cast<Eigen::Index>(std::ceil((c + 1) * framesPerColumn)) - 1));
    if (first >= values.size())
      break;
    const auto block = values.segment(first, last - first + 1);
    const double x = area.left() + c;
    const QPointF top(x, yOf(block.maxCoeff())), bottom(x, yOf(block.minCoeff()));
    painter.drawLine(top, bottom);
    if (havePrevious)
      painter.drawLine(previous, QPointF(x, yOf(block(0))));
    previous = QPointF(x, yOf(block(block.size() - 1)));
    havePrevious = true;
  }
}

} // namespace

MappedCurvePlot::MappedCurvePlot(QWidget* parent) : QWidget(parent)
{
  setMinimumHeight(70);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
}

void MappedCurvePlot::setCurves(Eigen::VectorXd mapped, Eigen::VectorXd source, const QString& label)
{
  m_mapped = std::move(mapped);
  m_source = std::move(source);
  m_label = label;
  update();
}

void MappedCurvePlot::clear()
{
  setCurves({}, {}, {});
}

void MappedCurvePlot::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  const QRectF area = QRectF(rect()).adjusted(4.0, 4.0, -4.0, -4.0);
  painter.fillRect(rect(), QColor(38, 41, 46));
  if (m_mapped.size() == 0)
    return;
  double lo = std::min(0.0, m_mapped.minCoeff()), hi = std::max(1.0, m_mapped.maxCoeff());
  if (m_source.size() > 0) {
    lo = std::min(lo, m_source.minCoeff());
    hi = std::max(hi, m_source.maxCoeff());
  }
  painter.setPen(QColor(90, 90, 96));
  for (const double level : {0.0, 1.0}) {
    const double y = area.bottom() - (level - lo) / (hi - lo) * area.height();
    painter.drawLine(QPointF(area.left(), y), QPointF(area.right(), y));
  }
  paintCurve(painter, area, m_source, lo, hi, QPen(QColor(140, 140, 150), 1.0));
  paintCurve(painter, area, m_mapped, lo, hi, QPen(QColor(90, 200, 250), 1.6));
  painter.setPen(QColor(230, 230, 230));
  painter.drawText(area.adjusted(4.0, 2.0, 0.0, 0.0), Qt::AlignLeft | Qt::AlignTop, m_label);
}

} // namespace mocap::ui
