// The one job runner every panel and dialog runs its background work on, without a window:
// progress reaches the end, Cancel stops the computation itself, the newest request wins.
#include "job_waits.h"

#include "document/job_runner.h"

#include <QSignalSpy>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

namespace mocap {
namespace {

using namespace std::chrono_literals;

/// Work of `steps` × 5 ms that checks in after every step; `ended` tells it stopped (either way).
auto steppedWork(int steps, int result, std::shared_ptr<std::atomic<bool>> ended)
{
  return [steps, result, ended](const JobControl& control) {
    try {
      for (int i = 0; i < steps; ++i) {
        control.checkpoint(static_cast<double>(i) / steps);
        std::this_thread::sleep_for(5ms);
      }
    } catch (const JobCancelled&) {
      *ended = true;
      throw;
    }
    control.reportNow(1.0);
    *ended = true;
    return result;
  };
}

TEST(JobRunner, ProgressRisesToTheEndAndTheResultArrivesOnce)
{
  ui::JobRunner runner;
  std::vector<double> fractions;
  QObject::connect(&runner, &ui::JobRunner::progressed, [&](double f, const QString&) { fractions.push_back(f); });
  QSignalSpy finished(&runner, &ui::JobRunner::finished);
  std::vector<int> delivered;
  auto ended = std::make_shared<std::atomic<bool>>(false);
  runner.start(steppedWork(40, 7, ended), [&](int value) { delivered.push_back(value); });
  EXPECT_TRUE(runner.running());
  ASSERT_TRUE(test::waitForJob(runner));
  EXPECT_EQ(delivered, std::vector<int>{7});
  EXPECT_EQ(finished.count(), 1);
  ASSERT_GE(fractions.size(), 2u) << "throttled to one report per 50 ms, over 200 ms";
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  EXPECT_DOUBLE_EQ(runner.fraction(), 1.0);
}

TEST(JobRunner, CancelStopsTheComputationItself)
{
  ui::JobRunner runner;
  QSignalSpy cancelled(&runner, &ui::JobRunner::cancelled);
  QSignalSpy progressed(&runner, &ui::JobRunner::progressed);
  bool delivered = false;
  auto ended = std::make_shared<std::atomic<bool>>(false);
  runner.start(steppedWork(4000, 1, ended), [&](int) { delivered = true; });  // 20 s unless stopped
  ASSERT_TRUE(progressed.wait(5000));
  const auto asked = std::chrono::steady_clock::now();
  runner.cancel();
  EXPECT_EQ(cancelled.count(), 1);
  EXPECT_TRUE(runner.cancelling());
  ASSERT_TRUE(test::waitForJob(runner, 5000));
  EXPECT_TRUE(*ended);
  EXPECT_LT(std::chrono::steady_clock::now() - asked, 1s) << "the computation ran on after Cancel";
  EXPECT_FALSE(delivered) << "a job that threw JobCancelled has no result";
}

TEST(JobRunner, TheNewestRequestWins)
{
  ui::JobRunner runner;
  std::vector<int> delivered;
  const auto keep = [&](int value) { delivered.push_back(value); };
  // The first observes its control: the second request stops it.
  auto firstEnded = std::make_shared<std::atomic<bool>>(false);
  runner.start(steppedWork(4000, 1, firstEnded), keep);
  // The second ignores its control and ends after the third has delivered: still never delivered.
  auto secondEnded = std::make_shared<std::atomic<bool>>(false);
  runner.start(
      [secondEnded](const JobControl&) {
        std::this_thread::sleep_for(400ms);
        *secondEnded = true;
        return 2;
      },
      keep);
  auto thirdEnded = std::make_shared<std::atomic<bool>>(false);
  runner.start(steppedWork(2, 3, thirdEnded), keep);
  ASSERT_TRUE(test::waitForJob(runner));
  EXPECT_EQ(delivered, std::vector<int>{3});
  EXPECT_TRUE(*firstEnded) << "the superseded job was not stopped";
  // Let the ignoring one end and its finished() come round: nothing more arrives.
  QSignalSpy more(&runner, &ui::JobRunner::finished);
  EXPECT_FALSE(more.wait(700));
  EXPECT_TRUE(*secondEnded);
  EXPECT_EQ(delivered, std::vector<int>{3});
}

TEST(JobRunner, AFailureIsReportedAndNothingDelivered)
{
  ui::JobRunner runner;
  QSignalSpy failed(&runner, &ui::JobRunner::failed);
  bool delivered = false;
  runner.start([](const JobControl&) -> int { throw std::runtime_error("disk full"); },
               [&](int) { delivered = true; });
  ASSERT_TRUE(test::waitForJob(runner));
  ASSERT_EQ(failed.count(), 1);
  EXPECT_EQ(failed.at(0).at(0).toString(), QStringLiteral("disk full"));
  EXPECT_FALSE(delivered);
}

// The command line's start-up: wait() delivers at once, without an event loop.
TEST(JobRunner, WaitDeliversWithoutTheEventLoop)
{
  ui::JobRunner runner;
  QSignalSpy finished(&runner, &ui::JobRunner::finished);
  int delivered = 0;
  runner.start([](const JobControl&) { return 5; }, [&](int value) { delivered = value; });
  runner.wait();
  EXPECT_EQ(delivered, 5);
  EXPECT_FALSE(runner.running());
  EXPECT_EQ(finished.count(), 1);
  EXPECT_FALSE(finished.wait(100)) << "the watcher's own end must not deliver a second time";
  EXPECT_EQ(delivered, 5);
}

} // namespace
} // namespace mocap
