#include "views/curve_view.h"

#include "commands/apply_patches_command.h"
#include "commands/record_step_command.h"
#include "document/take_document.h"
#include "views/display_units.h"
#include "views/sample_colors.h"
#include "views/axis_ticks.h"
#include "views/selection_palette.h"

#include "mocap/model/gaps.h"
#include "mocap/model/sample_patch.h"

#include <QKeyEvent>
#include <QUndoStack>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <QFontMetricsF>
#include <QPolygonF>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace mocap::ui {

namespace {
constexpr double kLeftMargin = 60.0;
constexpr double kRightMargin = 8.0;
constexpr double kTopMargin = 20.0;     // the legend row
constexpr double kBottomMargin = 30.0;  // frame and time tick labels
constexpr double kStripGap = 6.0;
const char* const kAxisNames[3] = {"X", "Y", "Z"};
const QColor kGrid(255, 255, 255, 26);
const QColor kTickText(150, 150, 150);

// The preview's colour: the marker's hue, much lighter than the curve drawn in it.
QColor previewColor(const QColor& marker)
{
  const float hue = marker.hslHueF();
  return QColor::fromHslF(hue < 0.0f ? 0.0f : hue, hue < 0.0f ? 0.0f : 1.0f, 0.86f);
}

double toDisplay(double value, LengthUnit from, LengthUnit to)
{
  return value * millimetresPer(from) / millimetresPer(to);
}
} // namespace

CurveView::CurveView(TakeDocument& document, QWidget* parent) : QWidget(parent), m_document(document)
{
  setFocusPolicy(Qt::StrongFocus);
  setMinimumHeight(150);
  setAutoFillBackground(false);
  setMouseTracking(true);  // the hover read-out
  connect(&document, &TakeDocument::takeReset, this, &CurveView::showAll);
  connect(&document, &TakeDocument::samplesChanged, this, qOverload<>(&CurveView::update));
  connect(&document, &TakeDocument::selectionChanged, this, qOverload<>(&CurveView::update));
  connect(&document, &TakeDocument::currentFrameChanged, this, &CurveView::follow);
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

void CurveView::follow(Eigen::Index frame)
{
  const auto f = static_cast<double>(frame);
  if (f < m_first || f > m_last) {
    const double span = m_last - m_first;
    setVisibleRange(f - span / 2.0, f + span / 2.0);
  }
  update();
}

QRectF CurveView::plotArea() const
{
  return QRectF(kLeftMargin, kTopMargin, std::max(width() - kLeftMargin - kRightMargin, 10.0),
                std::max(height() - kTopMargin - kBottomMargin, 10.0));
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

std::optional<std::pair<double, double>> CurveView::valueRange(int axis) const
{
  const Take& take = m_document.take();
  const auto& selection = m_document.selection();
  if (take.empty() || axis < 0 || axis > 2)
    return std::nullopt;
  const Eigen::Index first = std::max<Eigen::Index>(0, static_cast<Eigen::Index>(std::floor(m_first)));
  const Eigen::Index last = std::min<Eigen::Index>(take.frameCount() - 1, static_cast<Eigen::Index>(std::ceil(m_last)));
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (Eigen::Index m : selection) {
    const auto values = take.trajectory(m).col(axis);
    const auto valid = take.valid().col(m);
    for (Eigen::Index f = first; f <= last; ++f)
      if (valid(f)) {
        lo = std::min(lo, values(f));
        hi = std::max(hi, values(f));
      }
  }
  // The preview belongs in the range: a fill or stabilization proposal far from the curve is
  // exactly what there is to judge.
  for (const SamplePatch& patch : m_document.preview()) {
    if (!std::binary_search(selection.begin(), selection.end(), patch.marker))
      continue;
    for (std::size_t i = 0; i < patch.frames.size(); ++i) {
      const auto row = static_cast<Eigen::Index>(i);
      if (patch.frames[i] < first || patch.frames[i] > last || !patch.valid(row))
        continue;
      lo = std::min(lo, patch.positions(row, axis));
      hi = std::max(hi, patch.positions(row, axis));
    }
  }
  if (!std::isfinite(lo))
    return std::nullopt;
  const double margin = std::max((hi - lo) * 0.06, 0.5 * millimetresPer(LengthUnit::Millimetre) /
                                                       millimetresPer(take.units()));
  return std::pair(lo - margin, hi + margin);
}

void CurveView::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  painter.fillRect(rect(), QColor(30, 32, 36));
  const Take& take = m_document.take();
  const QRectF area = plotArea();
  for (StripScale& scale : m_scales)
    scale.drawn = false;
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
  // Current frame.
  const double x = xOf(static_cast<double>(m_document.currentFrame()));
  if (x >= area.left() && x <= area.right()) {
    painter.setPen(QPen(QColor(255, 255, 255, 160), 1.0));
    painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
  }
  paintFrameTicks(painter, area);
  paintLegend(painter);
  paintReadout(painter);
}

void CurveView::paintFrameTicks(QPainter& painter, const QRectF& area) const
{
  const Take& take = m_document.take();
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

void CurveView::paintLegend(QPainter& painter) const
{
  const Take& take = m_document.take();
  const auto& selection = m_document.selection();
  const QFontMetricsF metrics(painter.font());
  const double y = 3.0, h = 14.0;
  const double right = width() - kRightMargin;
  // Right-aligned key: the state halos and the preview.
  struct KeyItem
  {
    QString text;
    QColor color;
    bool dashed = false;
  };
  const bool preview = !m_document.preview().empty();
  const std::array<KeyItem, 4> all = {KeyItem{tr("preview"), previewColor(selectionPaletteColor(0)), true},
                                      KeyItem{tr("filled"), stateColor(SampleState::Filled), false},
                                      KeyItem{tr("smoothed"), stateColor(SampleState::Smoothed), false},
                                      KeyItem{tr("edited"), stateColor(SampleState::Edited), false}};
  const std::size_t firstKey = preview ? 0 : 1;
  double keyWidth = 0.0;
  for (std::size_t k = firstKey; k < all.size(); ++k)
    keyWidth += 22.0 + metrics.horizontalAdvance(all[k].text) + 10.0;
  double x = right - keyWidth;
  painter.setRenderHint(QPainter::Antialiasing, false);
  for (std::size_t k = firstKey; k < all.size(); ++k) {
    const KeyItem& item = all[k];
    const double mid = y + h / 2.0;
    if (item.dashed) {
      painter.setPen(QPen(item.color, 2.5, Qt::DashLine));
      painter.drawLine(QPointF(x, mid), QPointF(x + 18.0, mid));
    } else {
      QColor halo = item.color;
      halo.setAlpha(150);
      painter.setPen(QPen(halo, 5.0));
      painter.drawLine(QPointF(x, mid), QPointF(x + 18.0, mid));
      painter.setPen(QPen(QColor(200, 200, 200), 1.0));
      painter.drawLine(QPointF(x, mid), QPointF(x + 18.0, mid));
    }
    painter.setPen(kTickText);
    const double w = metrics.horizontalAdvance(item.text);
    painter.drawText(QRectF(x + 22.0, y, w + 2.0, h), Qt::AlignLeft | Qt::AlignVCenter, item.text);
    x += 22.0 + w + 10.0;
  }
  // Left: one swatch and label per selected marker, as many as fit before the key.
  const double limit = right - keyWidth - 12.0;
  x = kLeftMargin;
  for (std::size_t i = 0; i < selection.size(); ++i) {
    const QString label = QString::fromStdString(take.label(selection[i]));
    const double w = 16.0 + metrics.horizontalAdvance(label) + 12.0;
    const QString more = tr("+%1 more").arg(selection.size() - i);
    if (x + w > limit - (i + 1 < selection.size() ? metrics.horizontalAdvance(more) : 0.0)) {
      painter.setPen(kTickText);
      painter.drawText(QRectF(x, y, limit - x + 80.0, h), Qt::AlignLeft | Qt::AlignVCenter, more);
      break;
    }
    painter.fillRect(QRectF(x, y + 3.0, 11.0, h - 6.0), selectionPaletteColor(i));
    painter.setPen(QColor(215, 215, 215));
    painter.drawText(QRectF(x + 15.0, y, w, h), Qt::AlignLeft | Qt::AlignVCenter, label);
    x += w;
  }
}

void CurveView::paintStrip(QPainter& painter, const QRectF& strip, int axis) const
{
  const Take& take = m_document.take();
  const auto& selection = m_document.selection();
  painter.fillRect(strip, QColor(38, 41, 46));

  // Each marker's gaps, lightly in its colour, with a solid band at the top to tell them apart.
  for (std::size_t i = 0; i < selection.size(); ++i) {
    QColor light = selectionPaletteColor(i);
    QColor band = light;
    light.setAlpha(30);
    band.setAlpha(170);
    const double bandY = strip.top() + 3.0 * static_cast<double>(i % 6);
    for (const Gap& gap : findGaps(take.valid().col(selection[i]), selection[i])) {
      const double x0 = std::max(xOf(static_cast<double>(gap.firstFrame) - 0.5), strip.left());
      const double x1 = std::min(xOf(static_cast<double>(gap.firstFrame + gap.length) - 0.5), strip.right());
      if (x1 <= x0)
        continue;
      const double w = std::max(x1 - x0, 1.0);
      painter.fillRect(QRectF(x0, strip.top(), w, strip.height()), light);
      painter.fillRect(QRectF(x0, bandY, w, 3.0), band);
    }
  }

  const auto range = valueRange(axis);
  const QString axisName = QStringLiteral("%1 (%2)").arg(QLatin1String(kAxisNames[axis]), unitLabel(m_displayUnit));
  if (!range) {
    painter.setPen(QColor(170, 170, 170));
    painter.drawText(QRectF(strip.left() + 4.0, strip.top() + 1.0, 80.0, 14.0), Qt::AlignLeft | Qt::AlignTop, axisName);
    return;
  }
  const auto [lo, hi] = *range;
  m_scales[static_cast<std::size_t>(axis)] = {strip, lo, hi, true};
  paintValueTicks(painter, strip, axis, lo, hi);

  painter.save();
  painter.setClipRect(strip);
  for (std::size_t i = 0; i < selection.size(); ++i)
    paintCurve(painter, strip, selection[i], axis, selectionPaletteColor(i));
  paintPreview(painter, strip, axis);
  paintFlags(painter, strip, axis);
  painter.restore();
  // The axis name on a dark plate, so a curve passing the corner does not hide it.
  const QRectF plate(strip.left() + 2.0, strip.top() + 2.0,
                     QFontMetricsF(painter.font()).horizontalAdvance(axisName) + 8.0, 15.0);
  painter.fillRect(plate, QColor(30, 32, 36, 200));
  painter.setPen(QColor(190, 190, 190));
  painter.drawText(plate, Qt::AlignCenter, axisName);
}

void CurveView::paintValueTicks(QPainter& painter, const QRectF& strip, int axis, double lo, double hi) const
{
  const LengthUnit units = m_document.take().units();
  const double from = toDisplay(lo, units, m_displayUnit), to = toDisplay(hi, units, m_displayUnit);
  const AxisTicks ticks = niceTicks(from, to, std::max(4, static_cast<int>(strip.height() / 16.0)));
  const double scale = (hi - lo) / (to - from);  // take units per display unit
  const StripScale& s = m_scales[static_cast<std::size_t>(axis)];
  painter.setRenderHint(QPainter::Antialiasing, false);
  for (const double v : ticks.values) {
    const double y = s.yOf(lo + (v - from) * scale);
    painter.setPen(kGrid);
    painter.drawLine(QPointF(strip.left(), y), QPointF(strip.right(), y));
    painter.setPen(kTickText);
    painter.drawLine(QPointF(strip.left() - 3.0, y), QPointF(strip.left(), y));
    painter.drawText(QRectF(0.0, y - 7.0, kLeftMargin - 6.0, 14.0), Qt::AlignRight | Qt::AlignVCenter,
                     QString::number(v, 'f', ticks.decimals));
  }
}

// O(visible frames) for one marker: zoomed out, each pixel column draws its frames' min-max
// (joined to the previous column); zoomed in, one segment per pair of neighbouring samples.
// Lines are batched by colour, so a paint is a handful of drawLines calls.
void CurveView::paintCurve(QPainter& painter, const QRectF& strip, Eigen::Index marker, int axis,
                           const QColor& color) const
{
  const Take& take = m_document.take();
  const auto values = take.trajectory(marker).col(axis);
  const auto valid = take.valid().col(marker);
  const auto states = take.states().col(marker);
  const auto& scale = m_scales[static_cast<std::size_t>(axis)];
  const Eigen::Index first = std::max<Eigen::Index>(0, static_cast<Eigen::Index>(std::floor(m_first)));
  const Eigen::Index last = std::min<Eigen::Index>(take.frameCount() - 1, static_cast<Eigen::Index>(std::ceil(m_last)));
  QVector<QLineF> lines;
  std::array<QVector<QLineF>, 4> halos;  // by SampleState
  const double framesPerPixel = (m_last - m_first) / strip.width();
  if (framesPerPixel > 1.0) {
    const int columns = static_cast<int>(strip.width());
    lines.reserve(columns);
    double previous = 0.0;  // last value of the previous column
    bool joined = false;    // whether the previous column ended on a valid sample
    for (int c = 0; c < columns; ++c) {
      const auto f0 = std::max(first, static_cast<Eigen::Index>(std::floor(frameAt(strip.left() + c))));
      const auto f1 = std::min(last, static_cast<Eigen::Index>(std::floor(frameAt(strip.left() + c + 1))));
      double cmin = std::numeric_limits<double>::infinity(), cmax = -cmin;
      std::uint8_t state = 0;
      bool broken = false;
      for (Eigen::Index f = f0; f <= f1; ++f) {
        if (!valid(f)) {
          broken = true;
          continue;
        }
        cmin = std::min(cmin, values(f));
        cmax = std::max(cmax, values(f));
        state = std::max(state, states(f));
      }
      if (!std::isfinite(cmin)) {
        joined = false;
        continue;
      }
      if (joined && !broken) {
        cmin = std::min(cmin, previous);
        cmax = std::max(cmax, previous);
      }
      joined = valid(f1);
      previous = values(f1);
      const double x = strip.left() + c + 0.5;
      const QLineF line(QPointF(x, scale.yOf(cmin) + 0.5), QPointF(x, scale.yOf(cmax) - 0.5));
      lines.push_back(line);
      if (state != 0 && static_cast<std::size_t>(state) < halos.size())
        halos[static_cast<std::size_t>(state)].push_back(line);
    }
  } else {
    for (Eigen::Index f = std::max<Eigen::Index>(first, 1); f <= last; ++f) {
      if (!valid(f) || !valid(f - 1))
        continue;
      const QLineF line(QPointF(xOf(static_cast<double>(f - 1)), scale.yOf(values(f - 1))),
                        QPointF(xOf(static_cast<double>(f)), scale.yOf(values(f))));
      lines.push_back(line);
      const std::uint8_t state = std::max(states(f), states(f - 1));
      if (state != 0 && static_cast<std::size_t>(state) < halos.size())
        halos[static_cast<std::size_t>(state)].push_back(line);
    }
  }
  painter.setRenderHint(QPainter::Antialiasing, framesPerPixel <= 1.0);
  for (std::size_t state = 1; state < halos.size(); ++state) {
    if (halos[state].isEmpty())
      continue;
    QColor halo = stateColor(static_cast<SampleState>(state));
    halo.setAlpha(120);
    QPen pen(halo, 5.0);
    pen.setCapStyle(Qt::FlatCap);
    painter.setPen(pen);
    painter.drawLines(halos[state]);
  }
  painter.setPen(QPen(color, framesPerPixel <= 1.0 ? 1.5 : 1.0));
  painter.drawLines(lines);
  painter.setRenderHint(QPainter::Antialiasing, false);
}

// What Apply would write: per selected marker, a thick dashed line in a light tint of the
// marker's colour through the patch's runs of consecutive frames (one point per pixel column,
// the column's mean, when zoomed out), with dots on the samples once they are apart.
// O(patch size) per patch.
void CurveView::paintPreview(QPainter& painter, const QRectF& strip, int axis) const
{
  const auto& selection = m_document.selection();
  const auto& scale = m_scales[static_cast<std::size_t>(axis)];
  const double pixelsPerFrame = strip.width() / (m_last - m_first);
  // Antialiased wide dashes cost far more than the curve itself; zoomed out (a point per pixel
  // column) they look the same without it.
  painter.setRenderHint(QPainter::Antialiasing, pixelsPerFrame >= 1.0);
  for (const SamplePatch& patch : m_document.preview()) {
    const QColor marker = selectedMarkerColor(selection, patch.marker);
    if (!marker.isValid())
      continue;
    const QColor tint = previewColor(marker);
    QPen dashed(tint, 2.5, Qt::DashLine);
    dashed.setCapStyle(Qt::FlatCap);
    std::vector<QPolygonF> runs(1);
    double columnX = -1.0, sum = 0.0;
    int count = 0;
    Eigen::Index previousFrame = -2;
    auto flushColumn = [&] {
      if (count > 0)
        runs.back().push_back(QPointF(columnX, scale.yOf(sum / count)));
      count = 0;
      sum = 0.0;
    };
    for (std::size_t i = 0; i < patch.frames.size(); ++i) {
      const auto row = static_cast<Eigen::Index>(i);
      const Eigen::Index f = patch.frames[i];
      if (static_cast<double>(f) < m_first - 1.0 || static_cast<double>(f) > m_last + 1.0 || !patch.valid(row)) {
        previousFrame = -2;
        continue;
      }
      if (f != previousFrame + 1) {
        flushColumn();
        if (!runs.back().isEmpty())
          runs.emplace_back();
      }
      previousFrame = f;
      const double x = xOf(static_cast<double>(f));
      const double v = patch.positions(row, axis);
      if (pixelsPerFrame >= 1.0) {
        runs.back().push_back(QPointF(x, scale.yOf(v)));
        continue;
      }
      const double column = std::floor(x) + 0.5;
      if (column != columnX)
        flushColumn();
      columnX = column;
      sum += v;
      ++count;
    }
    flushColumn();
    const bool dots = pixelsPerFrame >= 4.0;
    for (const QPolygonF& run : runs) {
      if (run.size() > 1) {
        painter.setPen(dashed);
        painter.setBrush(Qt::NoBrush);
        painter.drawPolyline(run);
      }
      if (dots || run.size() <= 2) {
        painter.setPen(QPen(QColor(20, 20, 24), 1.0));
        painter.setBrush(tint);
        for (const QPointF& p : run)
          painter.drawEllipse(p, 2.6, 2.6);
      }
    }
  }
  painter.setBrush(Qt::NoBrush);
}

void CurveView::paintFlags(QPainter& painter, const QRectF& strip, int axis) const
{
  (void)strip;
  const auto& selection = m_document.selection();
  const auto& scale = m_scales[static_cast<std::size_t>(axis)];
  const Take& take = m_document.take();
  // Flags for review: rings in the flag colour on the flagged samples.
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setBrush(Qt::NoBrush);
  painter.setPen(QPen(colorScheme().flagged, 1.5));
  for (const auto& [marker, frame] : m_document.flags()) {
    if (!std::binary_search(selection.begin(), selection.end(), marker) ||
        static_cast<double>(frame) < m_first || static_cast<double>(frame) > m_last)
      continue;
    painter.drawEllipse(QPointF(xOf(static_cast<double>(frame)), scale.yOf(take.trajectory(marker)(frame, axis))),
                        4.0, 4.0);
  }
}

std::optional<CurveView::HoverSample> CurveView::sampleAt(const QPointF& position) const
{
  const Take& take = m_document.take();
  const auto frame = static_cast<Eigen::Index>(std::lround(frameAt(position.x())));
  if (take.empty() || frame < 0 || frame >= take.frameCount())
    return std::nullopt;
  for (int axis = 0; axis < 3; ++axis) {
    const StripScale& scale = m_scales[static_cast<std::size_t>(axis)];
    if (!scale.drawn || !scale.rect.contains(position))
      continue;
    std::optional<HoverSample> best;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (Eigen::Index m : m_document.selection()) {
      if (!take.isValid(frame, m))
        continue;
      const double distance = std::abs(scale.yOf(take.trajectory(m)(frame, axis)) - position.y());
      if (distance < bestDistance) {
        bestDistance = distance;
        best = HoverSample{m, frame, axis};
      }
    }
    return best;
  }
  return std::nullopt;
}

QString CurveView::readoutAt(const QPointF& position) const
{
  const auto sample = sampleAt(position);
  if (!sample)
    return {};
  const Take& take = m_document.take();
  QString text = tr("%1 · frame %2 (%3 s) · %4 %5 %6")
                     .arg(QString::fromStdString(take.label(sample->marker)))
                     .arg(static_cast<qlonglong>(take.firstFrame() + sample->frame))
                     .arg(take.timeOf(sample->frame), 0, 'f', 3)
                     .arg(QLatin1String(kAxisNames[sample->axis]),
                          formatLength(take.trajectory(sample->marker)(sample->frame, sample->axis), take.units(),
                                       m_displayUnit),
                          unitLabel(m_displayUnit));
  for (const SamplePatch& patch : m_document.preview()) {
    if (patch.marker != sample->marker)
      continue;
    const auto it = std::lower_bound(patch.frames.begin(), patch.frames.end(), sample->frame);
    if (it != patch.frames.end() && *it == sample->frame) {
      const auto row = static_cast<Eigen::Index>(it - patch.frames.begin());
      if (patch.valid(row))
        text += tr(" → preview %1").arg(formatLength(patch.positions(row, sample->axis), take.units(), m_displayUnit));
    }
  }
  return text;
}

void CurveView::paintReadout(QPainter& painter) const
{
  if (!m_hover || m_drag)
    return;
  const auto sample = sampleAt(*m_hover);
  if (!sample)
    return;
  const QString text = readoutAt(*m_hover);
  const StripScale& scale = m_scales[static_cast<std::size_t>(sample->axis)];
  const QPointF at(xOf(static_cast<double>(sample->frame)),
                   scale.yOf(m_document.take().trajectory(sample->marker)(sample->frame, sample->axis)));
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setPen(QPen(selectedMarkerColor(m_document.selection(), sample->marker), 1.5));
  painter.setBrush(Qt::NoBrush);
  painter.drawEllipse(at, 4.5, 4.5);
  // The box sits beside the cursor, flipped to stay inside the widget.
  const QFontMetricsF metrics(painter.font());
  QRectF box(0.0, 0.0, metrics.horizontalAdvance(text) + 12.0, metrics.height() + 6.0);
  box.moveTopLeft(*m_hover + QPointF(14.0, 12.0));
  if (box.right() > width() - 2.0)
    box.moveRight(m_hover->x() - 10.0);
  if (box.bottom() > height() - 2.0)
    box.moveBottom(m_hover->y() - 8.0);
  painter.setPen(QColor(90, 90, 96));
  painter.setBrush(QColor(20, 21, 24, 230));
  painter.drawRoundedRect(box, 3.0, 3.0);
  painter.setPen(QColor(235, 235, 235));
  painter.drawText(box, Qt::AlignCenter, text);
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
  m_document.undoStack()->push(makeRecordedEdit(
      m_document, std::move(patches),
      tr("Move %1 %2 at frame %3")
          .arg(QString::fromStdString(take.label(drag.marker)), kAxisNames[drag.axis])
          .arg(static_cast<qlonglong>(take.firstFrame() + drag.frame)),
      "edit sample", {{"axis", kAxisNames[drag.axis]}}));
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
  m_hover = event->buttons() == Qt::NoButton ? std::optional(event->position()) : std::nullopt;
  update();
}

void CurveView::leaveEvent(QEvent* event)
{
  m_hover.reset();
  update();
  QWidget::leaveEvent(event);
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
