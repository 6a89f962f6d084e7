#include "views/timeline_widget.h"

#include "document/take_document.h"
#include "views/sample_colors.h"
#include "views/steady_label.h"

#include "mocap/base/length_unit.h"
#include "mocap/model/gaps.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QStringList>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QStylePainter>
#include <QTimer>
#include <QToolButton>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <tuple>

namespace mocap::ui {

namespace {
const QColor kGapTickColor(55, 55, 65);  // "missing": apart from the flag red, the state colours and the style's blue

/// The time readout of `frame`.
QString timeText(const Take& take, Eigen::Index frame)
{
  return QStringLiteral("%1 s").arg(take.timeOf(frame), 0, 'f', 3);
}
} // namespace

/// The frame slider with the marks of gaps, bad points and the selected range under the handle.
class TimelineSlider final : public QSlider
{
public:
  TimelineSlider(TakeDocument& document, QWidget* parent) : QSlider(Qt::Horizontal, parent), m_document(document)
  {
    setMinimumHeight(24);
    setToolTip(TimelineWidget::tr("Dark: gaps, red: bad points under review — of the selected markers, or of all "
                                  "when none is selected. Yellow: the selected frame range."));
    const auto stale = [this] {
      m_columns = -1;
      update();
    };
    connect(&document, &TakeDocument::takeReset, this, stale);
    connect(&document, &TakeDocument::samplesChanged, this, stale);
    connect(&document, &TakeDocument::markersChanged, this, stale);
    connect(&document, &TakeDocument::selectionChanged, this, stale);
    connect(&document, &TakeDocument::flagsChanged, this, stale);
    connect(&document, &TakeDocument::visibilityChanged, this, stale);
    connect(&document, &TakeDocument::rangeChanged, this, qOverload<>(&QWidget::update));
  }

  /// x of frame `frame`, where the handle's centre is when the slider is at it.
  [[nodiscard]] int xOf(Eigen::Index frame) const
  {
    const auto [left, span] = groove();
    return left + QStyle::sliderPositionFromValue(minimum(), maximum(), static_cast<int>(frame), span);
  }
  [[nodiscard]] std::vector<std::pair<int, int>> gapSpans() const { return spans(ticks().gaps); }
  [[nodiscard]] std::vector<std::pair<int, int>> flagSpans() const { return spans(ticks().flags); }

protected:
  void paintEvent(QPaintEvent*) override
  {
    QStylePainter painter(this);
    QStyleOptionSlider option;
    initStyleOption(&option);
    option.subControls = QStyle::SC_SliderGroove;
    painter.drawComplexControl(QStyle::CC_Slider, option);
    const int mid = height() / 2;
    if (m_document.hasRange()) {
      QColor band = colorScheme().selection;
      band.setAlpha(110);
      const int x0 = xOf(m_document.rangeFirst()), x1 = xOf(m_document.rangeLast());
      painter.fillRect(QRect(x0, 1, std::max(x1 - x0 + 1, 2), height() - 2), band);
    }
    for (const auto& [x0, x1] : spans(ticks().gaps))
      painter.fillRect(QRect(x0, 2, x1 - x0 + 1, mid - 2), kGapTickColor);
    for (const auto& [x0, x1] : spans(ticks().flags))
      painter.fillRect(QRect(x0, mid, std::max(x1 - x0 + 1, 2), height() - mid - 2), colorScheme().flagged);
    option.subControls = QStyle::SC_SliderHandle;
    painter.drawComplexControl(QStyle::CC_Slider, option);
  }

private:
  struct Ticks
  {
    std::vector<std::uint8_t> gaps;  // one per pixel column of the groove's span
    std::vector<std::uint8_t> flags;
  };

  /// The x of the first frame and the span in pixels to the last (as the style places the handle).
  [[nodiscard]] std::pair<int, int> groove() const
  {
    QStyleOptionSlider option;
    initStyleOption(&option);
    const QRect grooveRect = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderGroove, this);
    const QRect handle = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, this);
    return {grooveRect.x() + handle.width() / 2, std::max(grooveRect.width() - handle.width(), 1)};
  }

  /// The marks per pixel column, recomputed when the take, selection, flags or width changed:
  /// O(#frames · #markers + #flags + width).
  const Ticks& ticks() const
  {
    const auto [left, grooveSpan] = groove();
    const int span = grooveSpan; // a lambda cannot capture a structured binding in C++17
    if (m_columns == span + 1 && m_left == left && m_maximum == maximum())
      return m_ticks;
    m_columns = span + 1;
    m_left = left;
    m_maximum = maximum();
    m_ticks.gaps.assign(static_cast<std::size_t>(m_columns), 0);
    m_ticks.flags.assign(static_cast<std::size_t>(m_columns), 0);
    const Take& take = m_document.take();
    const auto& selection = m_document.selection();
    auto column = [&](Eigen::Index frame) {
      return static_cast<std::size_t>(QStyle::sliderPositionFromValue(minimum(), maximum(), static_cast<int>(frame), span));
    };
    auto mark = [&](Eigen::Index m) {
      for (const Gap& gap : findGaps(take.valid().col(m), m))
        std::fill(m_ticks.gaps.begin() + static_cast<std::ptrdiff_t>(column(gap.firstFrame)),
                  m_ticks.gaps.begin() + static_cast<std::ptrdiff_t>(column(gap.firstFrame + gap.length - 1)) + 1, 1);
    };
    if (selection.empty())
      for (const Eigen::Index m : m_document.listedPoints())
        mark(m);
    for (Eigen::Index m : selection)
      mark(m);
    for (const auto& [marker, frame] : m_document.flags())
      if ((selection.empty() || std::binary_search(selection.begin(), selection.end(), marker)) && frame >= 0 &&
          frame < take.frameCount())
        m_ticks.flags[column(frame)] = 1;
    return m_ticks;
  }

  /// Runs of marked columns as [x0, x1] in widget coordinates. O(width).
  [[nodiscard]] std::vector<std::pair<int, int>> spans(const std::vector<std::uint8_t>& marks) const
  {
    std::vector<std::pair<int, int>> runs;
    const int n = static_cast<int>(marks.size());
    for (int c = 0; c < n; ++c) {
      if (!marks[static_cast<std::size_t>(c)])
        continue;
      const int start = c;
      while (c + 1 < n && marks[static_cast<std::size_t>(c + 1)])
        ++c;
      runs.emplace_back(m_left + start, m_left + c);
    }
    return runs;
  }

  TakeDocument& m_document;
  mutable Ticks m_ticks;
  mutable int m_columns = -1;  // −1: stale
  mutable int m_left = 0;
  mutable int m_maximum = 0;
};

TimelineWidget::TimelineWidget(TakeDocument& document, QWidget* parent) : QWidget(parent), m_document(document)
{
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 2, 4, 2);
  auto makeButton = [this, layout](QStyle::StandardPixmap icon, const QString& tip) {
    auto* button = new QToolButton(this);
    button->setIcon(style()->standardIcon(icon));
    button->setToolTip(tip);
    button->setAutoRaise(true);
    layout->addWidget(button);
    return button;
  };
  QToolButton* previousGap = makeButton(QStyle::SP_MediaSkipBackward, tr("Previous gap"));
  QToolButton* back = makeButton(QStyle::SP_MediaSeekBackward, tr("Previous frame (Left)"));
  m_play = makeButton(QStyle::SP_MediaPlay, tr("Play / pause (Space)"));
  QToolButton* forward = makeButton(QStyle::SP_MediaSeekForward, tr("Next frame (Right)"));
  QToolButton* nextGap = makeButton(QStyle::SP_MediaSkipForward, tr("Next gap"));
  m_loop = makeButton(QStyle::SP_BrowserReload, tr("Loop"));
  m_loop->setCheckable(true);
  m_loop->setChecked(true);
  m_slider = new TimelineSlider(document, this);
  layout->addWidget(m_slider, 1);
  m_frame = new QSpinBox(this);
  m_frame->setToolTip(tr("Frame"));
  layout->addWidget(m_frame);
  m_time = new QLabel(this);
  layout->addWidget(m_time);
  m_speedBox = new QComboBox(this);
  for (double s : {0.1, 0.25, 0.5, 1.0, 2.0, 4.0})
    m_speedBox->addItem(QStringLiteral("%1×").arg(s), s);
  m_speedBox->setCurrentIndex(3);
  m_speedBox->setToolTip(tr("Playback speed"));
  layout->addWidget(m_speedBox);

  m_timer = new QTimer(this);
  m_timer->setInterval(8);
  m_timer->setTimerType(Qt::PreciseTimer);
  connect(m_timer, &QTimer::timeout, this, &TimelineWidget::advance);
  connect(m_play, &QToolButton::clicked, this, &TimelineWidget::togglePlaying);
  connect(back, &QToolButton::clicked, this, [this] { step(-1); });
  connect(forward, &QToolButton::clicked, this, [this] { step(1); });
  connect(previousGap, &QToolButton::clicked, this, [this] { jumpToGap(-1); });
  connect(nextGap, &QToolButton::clicked, this, [this] { jumpToGap(1); });
  connect(m_slider, &QSlider::valueChanged, this, [this](int value) { m_document.setCurrentFrame(value); });
  connect(m_frame, qOverload<int>(&QSpinBox::valueChanged), this, [this](int value) {
    m_document.setCurrentFrame(static_cast<Eigen::Index>(value - m_document.take().firstFrame()));
  });
  connect(m_speedBox, qOverload<int>(&QComboBox::currentIndexChanged), this, [this] {
    m_speed = m_speedBox->currentData().toDouble();
    if (isPlaying()) {  // restart the clock so the new speed applies from here
      m_startFrame = m_document.currentFrame();
      m_clock.restart();
    }
  });
  connect(&document, &TakeDocument::takeReset, this, &TimelineWidget::syncFromDocument);
  connect(&document, &TakeDocument::markersChanged, this, &TimelineWidget::syncFromDocument);  // frames may change too
  connect(&document, &TakeDocument::selectionChanged, this, [this] {
    if (m_document.selection() != m_jumpSelection)
      m_jumpSelection.clear();  // the user chose markers: jumps stay within them
  });
  connect(&document, &TakeDocument::currentFrameChanged, this, &TimelineWidget::syncFromDocument);
  syncFromDocument();
}

void TimelineWidget::syncFromDocument()
{
  const Take& take = m_document.take();
  const auto last = static_cast<int>(std::max<Eigen::Index>(take.frameCount() - 1, 0));
  const auto frame = static_cast<int>(m_document.currentFrame());
  const QSignalBlocker sliderBlock(m_slider);
  const QSignalBlocker frameBlock(m_frame);
  m_slider->setRange(0, last);
  m_slider->setValue(frame);
  // A spin box's setRange relayouts its window even when the range stays (3 ms a frame under
  // Xvfb while scrubbing), so only a new take's range is set.
  const int firstFrame = static_cast<int>(take.firstFrame());
  if (m_frame->minimum() != firstFrame || m_frame->maximum() != firstFrame + last) {
    m_frame->setRange(firstFrame, firstFrame + last);
    fixLabelSizeFor(*m_time, timeText(take, last), 80);
  }
  m_frame->setValue(firstFrame + frame);
  m_time->setText(timeText(take, frame));
}

bool TimelineWidget::isPlaying() const
{
  return m_timer->isActive();
}

void TimelineWidget::setPlaying(bool playing)
{
  if (playing == isPlaying() || (playing && m_document.take().frameCount() < 2))
    return;
  if (playing) {
    if (m_document.currentFrame() >= m_document.take().frameCount() - 1)
      m_document.setCurrentFrame(0);
    m_startFrame = m_document.currentFrame();
    m_clock.start();
    m_timer->start();
  } else {
    m_timer->stop();
  }
  m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

void TimelineWidget::advance()
{
  const Take& take = m_document.take();
  const double elapsed = static_cast<double>(m_clock.nsecsElapsed()) * 1e-9;
  auto frame = m_startFrame + static_cast<Eigen::Index>(std::floor(elapsed * take.frameRate() * m_speed));
  if (frame >= take.frameCount()) {
    if (!m_loop->isChecked()) {
      m_document.setCurrentFrame(take.frameCount() - 1);
      setPlaying(false);
      return;
    }
    frame %= take.frameCount();
    m_startFrame = frame;
    m_clock.restart();
  }
  m_document.setCurrentFrame(frame);
}

void TimelineWidget::step(int frames)
{
  setPlaying(false);
  m_document.setCurrentFrame(m_document.currentFrame() + frames);
}

namespace {

// The nearest of `frames` after (direction > 0) or before (< 0) `current`; −1 when there is none.
Eigen::Index nearestInDirection(const std::vector<Eigen::Index>& frames, Eigen::Index current, int direction)
{
  Eigen::Index best = -1;
  for (Eigen::Index f : frames) {
    if (direction > 0 && f > current && (best < 0 || f < best))
      best = f;
    if (direction < 0 && f < current && (best < 0 || f > best))
      best = f;
  }
  return best;
}

} // namespace

void TimelineWidget::jumpTo(Eigen::Index frame)
{
  if (frame < 0)
    return;
  setPlaying(false);
  m_document.setCurrentFrame(frame);
}

void TimelineWidget::jumpToGap(int direction)
{
  const Take& take = m_document.take();
  const bool everyMarker = m_document.selection().empty() || m_document.selection() == m_jumpSelection;
  std::vector<Eigen::Index> markers = m_document.selection();
  if (everyMarker)
    markers = m_document.listedPoints();
  // Gaps in (frame, marker) order, from where the last jump went (or the current frame), so
  // gaps of several markers that start on one frame are each visited. O(#frames · #markers).
  const Eigen::Index current = m_document.currentFrame();
  const Eigen::Index from =
      current == m_jumpFrame ? m_jumpMarker : (direction > 0 ? std::numeric_limits<Eigen::Index>::max() : -1);
  const auto here = std::make_tuple(current, from);
  std::optional<Gap> best;
  for (Eigen::Index m : markers)
    for (const Gap& gap : findGaps(take.valid().col(m), m)) {
      const auto key = std::make_tuple(gap.firstFrame, gap.marker);
      const bool ahead = direction > 0 ? key > here : key < here;
      if (ahead && (!best || (direction > 0) == (key < std::make_tuple(best->firstFrame, best->marker))))
        best = gap;
    }
  if (!best) {
    emit message(direction > 0 ? tr("No gap after this frame") : tr("No gap before this frame"));
    return;
  }
  jumpTo(best->firstFrame);
  m_jumpFrame = best->firstFrame;
  m_jumpMarker = best->marker;
  if (everyMarker) {
    m_jumpSelection = {best->marker};
    m_document.setSelection(m_jumpSelection);
  }
  emit message(tr("Gap of %1 at frame %2 (%3 frames)")
                   .arg(QString::fromStdString(take.label(best->marker)))
                   .arg(static_cast<qlonglong>(take.firstFrame() + best->firstFrame))
                   .arg(static_cast<qlonglong>(best->length)));
}

void TimelineWidget::jumpToFlag(int direction)
{
  const auto& selection = m_document.selection();
  std::vector<std::pair<Eigen::Index, Eigen::Index>> flags;  // (marker, frame) of the markers jumped over
  std::vector<Eigen::Index> frames;
  for (const auto& [marker, frame] : m_document.flags())
    if (selection.empty() || std::binary_search(selection.begin(), selection.end(), marker)) {
      flags.emplace_back(marker, frame);
      frames.push_back(frame);
    }
  const Eigen::Index target = nearestInDirection(frames, m_document.currentFrame(), direction);
  if (target < 0) {
    emit message(direction > 0 ? tr("No bad point after this frame") : tr("No bad point before this frame"));
    return;
  }
  jumpTo(target);
  QStringList named;
  for (const auto& [marker, frame] : flags)
    if (frame == target)
      named << flagDescription(marker, frame);
  emit message(tr("Bad point at frame %1: %2")
                   .arg(static_cast<qlonglong>(m_document.take().firstFrame() + target))
                   .arg(named.join(QStringLiteral("; "))));
}

QString TimelineWidget::flagDescription(Eigen::Index marker, Eigen::Index frame) const
{
  const Take& take = m_document.take();
  const QString label = QString::fromStdString(take.label(marker));
  const bool inside = frame > 0 && frame + 1 < take.frameCount();
  if (!inside || !take.isValid(frame - 1, marker) || !take.isValid(frame + 1, marker) || !take.isValid(frame, marker))
    return label;
  // Why it stands out, whichever test flagged it: its distance from the mid-value of its
  // neighbours (the value a mid-value repair, eq. 10 of Wang et al., would move it by), the jump a
  // technician sees on the curve. O(1).
  const Eigen::Vector3d mid = (take.position(frame - 1, marker) + take.position(frame + 1, marker)) / 2.0;
  const double off = (take.position(frame, marker) - mid).norm();
  return tr("%1, %2 %3 off the mid-point of its neighbours")
      .arg(label)
      .arg(off, 0, 'f', 1)
      .arg(QString::fromUtf8(unitName(take.units()).data(), static_cast<int>(unitName(take.units()).size())));
}

int TimelineWidget::tickX(Eigen::Index frame) const
{
  return m_slider->xOf(frame);
}

std::vector<std::pair<int, int>> TimelineWidget::gapTickSpans() const
{
  return m_slider->gapSpans();
}

std::vector<std::pair<int, int>> TimelineWidget::flagTickSpans() const
{
  return m_slider->flagSpans();
}

} // namespace mocap::ui
