// Work that never blocks: opening a take, Track and Label and every cleaning preview run off
// the UI thread, which keeps serving its event loop; Cancel stops the computation itself; long
// jobs show progress with a time estimate.
#include "../core/test_support.h"
#include "job_waits.h"
#include "sample_window.h"

#include "actions/labelling_actions.h"
#include "dialogs/job_dialog.h"
#include "document/job_runner.h"
#include "document/take_document.h"
#include "main_window.h"
#include "panels/cleaning_panel.h"
#include "panels/cleaning_step.h"
#include "panels/head_stabilization_step.h"
#include "panels/job_progress_row.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/io/c3d_writer.h"

#include <QElapsedTimer>
#include <QPushButton>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

namespace mocap {
namespace {

/// Counts the UI thread's timer ticks while it runs: zero means the thread never served its loop.
class TickCounter
{
public:
  TickCounter()
  {
    m_timer.setInterval(1);
    QObject::connect(&m_timer, &QTimer::timeout, [this] { ++m_ticks; });
    m_timer.start();
  }
  [[nodiscard]] int ticks() const { return m_ticks; }

private:
  QTimer m_timer;
  int m_ticks = 0;
};

constexpr Eigen::Index kLongFrames = 30000;

/// The sample repeated to 30 000 frames, written to `dir`: long enough that reading or
/// searching it outlasts a timer tick on any machine.
QString writeLongTake(const test::TempDir& dir)
{
  const Take sample = readC3d(test::sampleTake());
  Take take(sample.labels(), kLongFrames, sample.frameRate());
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    for (Eigen::Index f = 0; f < kLongFrames; ++f) {
      const Eigen::Index from = f % sample.frameCount();
      take.setPosition(f, m, sample.position(from, m));
      take.valid()(f, m) = sample.valid()(from, m);
      take.residuals()(f, m) = sample.residuals()(from, m);
    }
  writeC3d(take, dir.file("long.c3d"));
  return QString::fromStdString(dir.file("long.c3d").string());
}

TEST(BackgroundJobs, OpeningATakeKeepsTheEventLoopServed)
{
  auto window = test::openSampleWindow();
  ASSERT_TRUE(window);
  test::TempDir dir;
  const QString path = writeLongTake(dir);
  TickCounter counter;
  ASSERT_EQ(window->openFile(path, true), QString());
  EXPECT_GT(counter.ticks(), 0) << "the file was read on the UI thread";
  EXPECT_EQ(window->document().take().frameCount(), kLongFrames);
}

TEST(BackgroundJobs, TrackAndLabelAndTheSwapSearchKeepTheEventLoopServed)
{
  auto window = test::openSampleWindow();
  ASSERT_TRUE(window);
  test::TempDir dir;
  ASSERT_EQ(window->openFile(writeLongTake(dir), true), QString());
  {
    TickCounter counter;
    window->labellingActions()->trackAndLabel();
    EXPECT_GT(counter.ticks(), 0) << "Track and Label ran on the UI thread";
  }
  TickCounter counter;
  const auto swaps = window->labellingActions()->findSwaps();
  ASSERT_TRUE(swaps.has_value());
  EXPECT_GT(counter.ticks(), 0) << "the swap search ran on the UI thread";
}

/// A step whose computation runs until cancelled (or 20 s), to see whether Cancel stops it.
class EndlessStep final : public ui::CleaningStep
{
public:
  using CleaningStep::CleaningStep;
  [[nodiscard]] QString title() const override { return QStringLiteral("Endless"); }
  [[nodiscard]] ui::StepJob job() const override
  {
    return [ended = m_ended](const Take&, const JobControl& control) {
      const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      try {
        for (double f = 0.0; std::chrono::steady_clock::now() < until; f = std::min(f + 0.001, 0.99)) {
          control.checkpoint(f);
          std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
      } catch (const JobCancelled&) {
        *ended = true;
        throw;
      }
      *ended = true;
      return ui::StepResult{};
    };
  }
  std::shared_ptr<std::atomic<bool>> m_ended = std::make_shared<std::atomic<bool>>(false);
};

TEST(BackgroundJobs, CancelStopsTheComputationItselfAndProgressShowsTimeLeft)
{
  auto window = test::openSampleWindow();
  ASSERT_TRUE(window);
  ui::CleaningPanel* panel = window->cleaningPanel();
  auto* step = new EndlessStep(panel);
  panel->addStep(step);
  panel->setCurrentStep(step);
  panel->refresh();
  ASSERT_TRUE(panel->busy());
  auto* row = panel->findChild<ui::JobProgressRow*>();
  ASSERT_NE(row, nullptr);
  EXPECT_TRUE(row->cancelButton()->isEnabled());
  QTest::qWait(1200);  // long enough for an estimate
  EXPECT_TRUE(row->estimateText().contains(QStringLiteral("left"))) << row->estimateText().toStdString();
  QTest::mouseClick(row->cancelButton(), Qt::LeftButton);
  QElapsedTimer clock;
  clock.start();
  while (!*step->m_ended && clock.elapsed() < 5000)
    QTest::qWait(10);
  EXPECT_TRUE(*step->m_ended);
  EXPECT_LT(clock.elapsed(), 1000) << "Cancel left the computation running";
  EXPECT_FALSE(row->cancelButton()->isEnabled());
}

// Apply on a stale preview (live preview off, or pressed while it computes) does not block the
// window: it starts the computation and applies the preview when it arrives.
TEST(BackgroundJobs, ApplyOnAStalePreviewAppliesItWhenItArrives)
{
  auto window = test::openSampleWindow();
  ASSERT_TRUE(window);
  ui::CleaningPanel* panel = window->cleaningPanel();
  auto* step = panel->step<ui::HeadStabilizationStep>();
  ASSERT_NE(step, nullptr);
  panel->setCurrentStep(step);
  panel->refresh();
  ASSERT_FALSE(panel->previewReady());
  QUndoStack& edits = *window->document().undoStack();
  const int before = edits.count();
  EXPECT_EQ(panel->apply(), 0) << "nothing to apply before the preview exists";
  EXPECT_EQ(edits.count(), before);
  EXPECT_TRUE(panel->busy());
  ASSERT_TRUE(test::waitForJob(panel->jobs()));
  EXPECT_EQ(edits.count(), before + 1) << panel->statusText().toStdString();
  EXPECT_TRUE(panel->statusText().startsWith(QStringLiteral("Applied"))) << panel->statusText().toStdString();
}

// While a worker reads the document, the window refuses to close (it would free what is read).
TEST(BackgroundJobs, TheWindowDoesNotCloseUnderARunningJob)
{
  auto window = test::openSampleWindow();
  ASSERT_TRUE(window);
  bool closed = true, running = false;
  QTimer::singleShot(50, window.get(), [&] {  // served by runJob's event loop
    running = ui::jobRunning();
    closed = window->close();
  });
  EXPECT_TRUE(ui::runJob(window.get(), QStringLiteral("waiting"), [](const JobControl& control) {
    for (int i = 0; i < 30; ++i) {
      control.checkpoint(i / 30.0);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }));
  EXPECT_TRUE(running);
  EXPECT_FALSE(closed);
  EXPECT_TRUE(window->isVisible());
  EXPECT_FALSE(ui::jobRunning());
}

TEST(BackgroundJobs, TimeLeftAssumesAnEvenPaceAndWaitsUntilItCanTell)
{
  EXPECT_TRUE(ui::timeLeftText(0.5, 0.2).isEmpty());   // too early
  EXPECT_TRUE(ui::timeLeftText(0.01, 5.0).isEmpty());  // too little done
  EXPECT_EQ(ui::timeLeftText(0.25, 3.0), QStringLiteral("about 9 s left"));
  EXPECT_EQ(ui::timeLeftText(0.1, 60.0), QStringLiteral("about 9 min left"));
}

} // namespace
} // namespace mocap
