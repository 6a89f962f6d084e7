#include "views/timeline_widget.h"

#include "document/take_document.h"

#include "mocap/gaps.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QTimer>
#include <QToolButton>

#include <cmath>

namespace mocap::ui {

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
  m_slider = new QSlider(Qt::Horizontal, this);
  layout->addWidget(m_slider, 1);
  m_frame = new QSpinBox(this);
  m_frame->setToolTip(tr("Frame"));
  layout->addWidget(m_frame);
  m_time = new QLabel(this);
  m_time->setMinimumWidth(80);
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
  m_frame->setRange(static_cast<int>(take.firstFrame()), static_cast<int>(take.firstFrame()) + last);
  m_frame->setValue(static_cast<int>(take.firstFrame()) + frame);
  m_time->setText(QStringLiteral("%1 s").arg(take.timeOf(frame), 0, 'f', 3));
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
  std::vector<Eigen::Index> markers = m_document.selection();
  if (markers.empty())
    for (Eigen::Index m = 0; m < take.markerCount(); ++m)
      markers.push_back(m);
  std::vector<Eigen::Index> starts;
  for (Eigen::Index m : markers)
    for (const Gap& gap : findGaps(take.valid().col(m), m))
      starts.push_back(gap.firstFrame);
  jumpTo(nearestInDirection(starts, m_document.currentFrame(), direction));
}

void TimelineWidget::jumpToFlag(int direction)
{
  const auto& selection = m_document.selection();
  std::vector<Eigen::Index> frames;
  for (const auto& [marker, frame] : m_document.flags())
    if (selection.empty() || std::binary_search(selection.begin(), selection.end(), marker))
      frames.push_back(frame);
  jumpTo(nearestInDirection(frames, m_document.currentFrame(), direction));
}

} // namespace mocap::ui
