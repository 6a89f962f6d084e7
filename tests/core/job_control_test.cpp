// Progress and cancellation of long computations: a cancelled job stops in the computation
// itself (JobCancelled), and progress rises to the end of the part it belongs to.
#include "test_support.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/cleaning/fill/gap_fill.h"
#include "mocap/base/job_control.h"
#include "mocap/cleaning/smoothing.h"
#include "mocap/cleaning/spike_detection.h"
#include "mocap/tracking/swap_detection.h"
#include "mocap/tracking/take_tracking.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>
#include <vector>

namespace mocap {
namespace {

TEST(JobControl, DefaultDoesNothing)
{
  const JobControl none;
  EXPECT_FALSE(none.cancelled());
  EXPECT_NO_THROW(none.checkpoint(0.5));
}

TEST(JobControl, CancelThrowsAtTheNextCheckpoint)
{
  auto cancel = std::make_shared<std::atomic<bool>>(false);
  const JobControl job({}, cancel);
  EXPECT_NO_THROW(job.checkpoint(0.1));
  *cancel = true;
  EXPECT_TRUE(job.cancelled());
  EXPECT_THROW(job.checkpoint(0.2), JobCancelled);
  EXPECT_THROW(job.part(0.5, 1.0).checkpoint(0.0), JobCancelled);
}

TEST(JobControl, PartMapsProgressIntoItsShareAndThrottles)
{
  std::vector<double> reported;
  const JobControl job([&](double f) { reported.push_back(f); }, nullptr);
  const auto start = std::chrono::steady_clock::now();
  job.part(0.5, 1.0).checkpoint(0.5);
  ASSERT_EQ(reported.size(), 1u);
  EXPECT_DOUBLE_EQ(reported.back(), 0.75);
  job.checkpoint(0.9);  // within 50 ms of the last report: throttled
  if (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(40)) {  // unless this thread stalled
    EXPECT_EQ(reported.size(), 1u);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  job.part(0.0, 0.5).part(0.5, 1.0).checkpoint(2.0);  // clamped to the part's end
  ASSERT_EQ(reported.size(), 2u);
  EXPECT_DOUBLE_EQ(reported.back(), 0.5);
}

// What the layout planning runs on: report() never throws (the run returns what is complete),
// reportNow() passes the throttle, silent() stops but does not report, threads go with parts.
TEST(JobControl, ReportsWithoutThrowingAndCarriesThreads)
{
  std::vector<double> reported;
  auto cancel = std::make_shared<std::atomic<bool>>(true);
  const JobControl job = JobControl([&](double f) { reported.push_back(f); }, cancel).withThreads(3);
  EXPECT_NO_THROW(job.report(0.25));
  job.reportNow(0.5);  // within 50 ms of the last: forced
  ASSERT_EQ(reported.size(), 2u);
  EXPECT_DOUBLE_EQ(reported.back(), 0.5);
  EXPECT_EQ(job.cancelFlag(), cancel.get());
  EXPECT_EQ(job.part(0.0, 0.5).threads(), 3);
  EXPECT_EQ(JobControl().threads(), 0);
  EXPECT_EQ(JobControl().cancelFlag(), nullptr);
  const JobControl quiet = job.silent();
  quiet.reportNow(1.0);
  EXPECT_EQ(reported.size(), 2u);
  EXPECT_THROW(quiet.checkpoint(0.0), JobCancelled);
}

// Each long core step stops when cancelled instead of running to the end.
TEST(JobControl, CancelledStepsOnTheSampleThrow)
{
  const Take take = readC3d(test::sampleTake());
  const JobControl job({}, std::make_shared<std::atomic<bool>>(true));
  EXPECT_THROW((void)fillGaps(take, FillOptions{}, job), JobCancelled);
  EXPECT_THROW((void)smoothTake(take, SmoothOptions{}, job), JobCancelled);
  EXPECT_THROW((void)detectSpikes(take, SpikeOptions{}, job), JobCancelled);
  EXPECT_THROW((void)detectSwaps(take, {}, job), JobCancelled);
  EXPECT_THROW((void)trackTake(take, nullptr, {}, nullptr, job), JobCancelled);
}

TEST(JobControl, TrackingReportsRisingProgress)
{
  const Take take = readC3d(test::sampleTake());
  std::vector<double> reported;
  const JobControl job([&](double f) { reported.push_back(f); }, std::make_shared<std::atomic<bool>>(false));
  TrackReport report;
  const Take tracked = trackTake(take, nullptr, {}, &report, job);
  EXPECT_EQ(tracked.frameCount(), take.frameCount());
  ASSERT_FALSE(reported.empty());
  for (std::size_t i = 1; i < reported.size(); ++i)
    EXPECT_GE(reported[i], reported[i - 1]);
  EXPECT_LE(reported.back(), 1.0);
}

} // namespace
} // namespace mocap
