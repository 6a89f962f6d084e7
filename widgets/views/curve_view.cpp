#include "views/curve_view.h"

#include "commands/apply_patches_command.h"
#include "commands/record_step_command.h"
#include "document/take_document.h"
#include "document/view_state.h"
#include "views/display_units.h"
#include "views/sample_colors.h"
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
#include <optional>
#include <utility>

namespace mocap::ui {

namespace {
const char* const kAxisNames[3] = {"X", "Y", "Z"};
const QColor kTickText(150, 150, 150);

// The preview's colour: the marker's hue, much lighter than the curve drawn in it.
QColor previewColor(const QColor& marker)
{
  const float hue = marker.hslHueF();
  return QColor::fromHslF(hue < 0.0f ? 0.0f : hue, hue < 0.0f ? 0.0f : 1.0f, 0.86f);
}

using HaloLines = std::array<QVector<QLineF>, kSampleMarkCount>;

// Files a curve segment under its halo: `mark` (the primary, none for an untouched sample) and,
// when `second`, the smoothed rim drawn beneath a made sample's halo.
void addHalo(HaloLines& halos, QVector<QLineF>& secondHalos, const QLineF& line, SampleMark mark, bool second)
{
  if (mark != SampleMark::None)
    halos[static_cast<std::size_t>(mark)].push_back(line);
  if (second)
    secondHalos.push_back(line);
}

void drawHalo(QPainter& painter, const QVector<QLineF>& lines, QColor color, double width)
{
  if (lines.isEmpty())
    return;
  color.setAlpha(120);
  QPen pen(color, width);
  pen.setCapStyle(Qt::FlatCap);
  painter.setPen(pen);
  painter.drawLines(lines);
}

double toDisplay(double value, LengthUnit from, LengthUnit to)
{
  return value * millimetresPer(from) / millimetresPer(to);
}
} // namespace

CurveView::CurveView(TakeDocument& document, QWidget* parent)
    : FrameStripView(document, parent), m_document(document)
{
  setMinimumHeight(150);
  setMouseTracking(true);  // the hover read-out
  connect(&document, &TakeDocument::samplesChanged, this, qOverload<>(&CurveView::update));
  connect(&document, &TakeDocument::selectionChanged, this, qOverload<>(&CurveView::update));
  connect(&document, &TakeDocument::previewChanged, this, qOverload<>(&CurveView::update));
  connect(&document, &TakeDocument::flagsChanged, this, qOverload<>(&CurveView::update));
  connect(&document, &TakeDocument::markersChanged, this, qOverload<>(&CurveView::update));
}

void CurveView::setDisplayUnit(LengthUnit unit)
{
  m_displayUnit = unit;
  update();
}

void CurveView::observe(const ViewState& state)
{
  setDisplayUnit(state.displayUnit());
  connect(&state, &ViewState::displayUnitChanged, this, &CurveView::setDisplayUnit);
  connect(&state, &ViewState::colorsChanged, this, qOverload<>(&QWidget::update));
}

std::optional<std::pair<double, double>> CurveView::valueRange(int axis) const
{
  const Take& take = m_document.take();
  const auto& selection = m_document.selection();
  if (take.empty() || axis < 0 || axis > 2)
    return std::nullopt;
  const Eigen::Index first = std::max<Eigen::Index>(0, static_cast<Eigen::Index>(std::floor(firstVisible())));
  const Eigen::Index last = std::min<Eigen::Index>(take.frameCount() - 1, static_cast<Eigen::Index>(std::ceil(lastVisible())));
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
  for (StripScale& scale : m_scales)
    scale.drawn = false;
  if (take.empty() || m_document.selection().empty()) {
    painter.setPen(QColor(160, 160, 160));
    painter.drawText(rect(), Qt::AlignCenter, tr("Select a marker to see its curves"));
    return;
  }
  const std::vector<QRectF> axes = strips(3);
  for (int axis = 0; axis < 3; ++axis)
    paintStrip(painter, axes[static_cast<std::size_t>(axis)], axis);
  paintFrameOverlay(painter);
  paintLegend(painter);
  paintReadout(painter);
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
                                      KeyItem{tr("filled"), markColor(SampleMark::Filled), false},
                                      KeyItem{tr("smoothed"), markColor(SampleMark::Smoothed), false},
                                      KeyItem{tr("edited"), markColor(SampleMark::Edited), false}};
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
  std::vector<QString> labels;
  std::vector<QColor> colors;
  for (std::size_t i = 0; i < selection.size(); ++i) {
    labels.push_back(QString::fromStdString(take.label(selection[i])));
    colors.push_back(selectionPaletteColor(i));
  }
  paintSwatchLegend(painter, labels, colors, right - keyWidth - 12.0);
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
  paintValueTicks(painter, strip, lo, hi);

  painter.save();
  painter.setClipRect(strip);
  for (std::size_t i = 0; i < selection.size(); ++i)
    paintCurve(painter, strip, selection[i], axis, selectionPaletteColor(i));
  paintPreview(painter, strip, axis);
  paintFlags(painter, strip, axis);
  painter.restore();
  paintStripName(painter, strip, axisName);
}

void CurveView::paintValueTicks(QPainter& painter, const QRectF& strip, double lo, double hi) const
{
  const LengthUnit units = m_document.take().units();
  FrameStripView::paintValueTicks(painter, strip, toDisplay(lo, units, m_displayUnit), toDisplay(hi, units, m_displayUnit));
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
  const Eigen::Index first = std::max<Eigen::Index>(0, static_cast<Eigen::Index>(std::floor(firstVisible())));
  const Eigen::Index last = std::min<Eigen::Index>(take.frameCount() - 1, static_cast<Eigen::Index>(std::ceil(lastVisible())));
  QVector<QLineF> lines;
  HaloLines halos;  // by primaryMark
  QVector<QLineF> secondHalos;  // made samples that were also smoothed: a smoothed rim around the halo
  const double framesPerPixel = (lastVisible() - firstVisible()) / strip.width();
  if (framesPerPixel > 1.0) {
    const int columns = static_cast<int>(strip.width());
    lines.reserve(columns);
    double previous = 0.0;  // last value of the previous column
    bool joined = false;    // whether the previous column ended on a valid sample
    for (int c = 0; c < columns; ++c) {
      const auto f0 = std::max(first, static_cast<Eigen::Index>(std::floor(frameAt(strip.left() + c))));
      const auto f1 = std::min(last, static_cast<Eigen::Index>(std::floor(frameAt(strip.left() + c + 1))));
      double cmin = std::numeric_limits<double>::infinity(), cmax = -cmin;
      SampleMark mark = SampleMark::None;
      bool second = false;
      bool broken = false;
      for (Eigen::Index f = f0; f <= f1; ++f) {
        if (!valid(f)) {
          broken = true;
          continue;
        }
        cmin = std::min(cmin, values(f));
        cmax = std::max(cmax, values(f));
        const SampleState state = SampleState::fromBits(states(f));
        mark = std::max(mark, primaryMark(state));
        second = second || secondaryMark(state) != SampleMark::None;
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
      addHalo(halos, secondHalos, line, mark, second);
    }
  } else {
    for (Eigen::Index f = std::max<Eigen::Index>(first, 1); f <= last; ++f) {
      if (!valid(f) || !valid(f - 1))
        continue;
      const QLineF line(QPointF(xOf(static_cast<double>(f - 1)), scale.yOf(values(f - 1))),
                        QPointF(xOf(static_cast<double>(f)), scale.yOf(values(f))));
      lines.push_back(line);
      const SampleState a = SampleState::fromBits(states(f - 1)), b = SampleState::fromBits(states(f));
      addHalo(halos, secondHalos, line, std::max(primaryMark(a), primaryMark(b)),
              secondaryMark(a) != SampleMark::None || secondaryMark(b) != SampleMark::None);
    }
  }
  painter.setRenderHint(QPainter::Antialiasing, framesPerPixel <= 1.0);
  drawHalo(painter, secondHalos, markColor(SampleMark::Smoothed), 9.0);
  for (std::size_t mark = 1; mark < halos.size(); ++mark)
    drawHalo(painter, halos[mark], markColor(static_cast<SampleMark>(mark)), 5.0);
  painter.setPen(QPen(color, framesPerPixel <= 1.0 ? 1.5 : 1.0));
  painter.drawLines(lines);
  painter.setRenderHint(QPainter::Antialiasing, false);
}

// What Apply would write: per selected marker, a thick dashed line in a light tint of the
// marker's colour through the patch's runs of consecutive frames (one point per pixel column,
// the column's mean, when zoomed out), with dots on the samples once they are apart. Zoomed in, a
// run is joined to the take's kept samples either side, so a single repaired sample (a bad
// point) reads as a dashed detour from its neighbours, not a lone dot. O(patch size) per patch.
void CurveView::paintPreview(QPainter& painter, const QRectF& strip, int axis) const
{
  struct Run
  {
    QPolygonF points;
    bool leading = false;  // points.front() is the take's sample before the run
    bool trailing = false;  // points.back() is the take's sample after it
  };
  const Take& take = m_document.take();
  const auto& selection = m_document.selection();
  const auto& scale = m_scales[static_cast<std::size_t>(axis)];
  const double pixelsPerFrame = strip.width() / (lastVisible() - firstVisible());
  // Antialiased wide dashes cost far more than the curve itself; zoomed out (a point per pixel
  // column) they look the same without it.
  painter.setRenderHint(QPainter::Antialiasing, pixelsPerFrame >= 1.0);
  for (const SamplePatch& patch : m_document.preview()) {
    const QColor marker = selectedMarkerColor(selection, patch.marker);
    if (!marker.isValid() || patch.marker >= take.markerCount())
      continue;
    const QColor tint = previewColor(marker);
    QPen dashed(tint, 2.5, Qt::DashLine);
    dashed.setCapStyle(Qt::FlatCap);
    // The take's sample at `frame` as a point, when it is kept (valid and not in the patch).
    const auto kept = [&](Eigen::Index frame, bool inPatch) -> std::optional<QPointF> {
      if (inPatch || frame < 0 || frame >= take.frameCount() || !take.isValid(frame, patch.marker))
        return std::nullopt;
      return QPointF(xOf(static_cast<double>(frame)), scale.yOf(take.position(frame, patch.marker)(axis)));
    };
    std::vector<Run> runs(1);
    double columnX = -1.0, sum = 0.0;
    int count = 0;
    Eigen::Index previousFrame = -2;
    auto flushColumn = [&] {
      if (count > 0)
        runs.back().points.push_back(QPointF(columnX, scale.yOf(sum / count)));
      count = 0;
      sum = 0.0;
    };
    for (std::size_t i = 0; i < patch.frames.size(); ++i) {
      const auto row = static_cast<Eigen::Index>(i);
      const Eigen::Index f = patch.frames[i];
      if (static_cast<double>(f) < firstVisible() - 1.0 || static_cast<double>(f) > lastVisible() + 1.0 || !patch.valid(row)) {
        previousFrame = -2;
        continue;
      }
      if (f != previousFrame + 1) {
        flushColumn();
        if (!runs.back().points.isEmpty())
          runs.emplace_back();
      }
      const double x = xOf(static_cast<double>(f));
      const double v = patch.positions(row, axis);
      if (pixelsPerFrame >= 1.0) {
        if (f != previousFrame + 1)
          if (const auto before = kept(f - 1, i > 0 && patch.frames[i - 1] == f - 1)) {
            runs.back().points.push_back(*before);
            runs.back().leading = true;
          }
        runs.back().points.push_back(QPointF(x, scale.yOf(v)));
        if (i + 1 == patch.frames.size() || patch.frames[i + 1] != f + 1)
          if (const auto after = kept(f + 1, false)) {
            runs.back().points.push_back(*after);
            runs.back().trailing = true;
          }
        previousFrame = f;
        continue;
      }
      previousFrame = f;
      const double column = std::floor(x) + 0.5;
      if (column != columnX)
        flushColumn();
      columnX = column;
      sum += v;
      ++count;
    }
    flushColumn();
    const bool dots = pixelsPerFrame >= 4.0;
    for (const Run& run : runs) {
      if (run.points.size() > 1) {
        painter.setPen(dashed);
        painter.setBrush(Qt::NoBrush);
        painter.drawPolyline(run.points);
      }
      const qsizetype first = run.leading ? 1 : 0;
      const qsizetype last = run.points.size() - (run.trailing ? 1 : 0);  // the preview's own samples
      if (dots || last - first <= 2) {
        painter.setPen(QPen(QColor(20, 20, 24), 1.0));
        painter.setBrush(tint);
        for (qsizetype k = first; k < last; ++k)
          painter.drawEllipse(run.points[k], 2.6, 2.6);
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
        static_cast<double>(frame) < firstVisible() || static_cast<double>(frame) > lastVisible())
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
  if (const SampleState state = take.state(sample->frame, sample->marker); !state.untouched())
    text += QStringLiteral(" · ") + stateText(state);
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
  if ((lastVisible() - firstVisible()) / plotArea().width() > 0.5)
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
  return makePatch(m_drag->marker, {m_drag->frame}, moved.transpose(), SampleOrigin::Edited);
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

bool CurveView::pressItem(const QPointF& position)
{
  return startDrag(position);
}

void CurveView::mouseMoveEvent(QMouseEvent* event)
{
  if (m_drag && (event->buttons() & Qt::LeftButton))
    updateDrag(event->position());
  else
    FrameStripView::mouseMoveEvent(event);
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
  FrameStripView::mouseReleaseEvent(event);
  if (m_drag && event->button() == Qt::LeftButton)
    finishDrag(std::abs(event->position().y() - m_drag->startY) >= 1.0 ? std::optional(event->position())
                                                                        : std::nullopt);
}

void CurveView::keyPressEvent(QKeyEvent* event)
{
  if (event->key() == Qt::Key_Escape && m_drag)
    finishDrag(std::nullopt);
  else
    FrameStripView::keyPressEvent(event);
}

} // namespace mocap::ui
