// The Reference Video dock under Xvfb, on a copy of the sample take (its sidecar is written beside
// it): videos the test writes (each frame shows its number as a bar code, at 25 and 30 fps against
// the sample's 100 Hz), stepped through with the take — forward, backwards and by jumps — show
// exactly the video frame each one's offset maps each take frame to; several videos per take,
// remembered beside it and restored on reopening (a missing one kept and located); Sync here and
// Sync to event.
#include "coded_image.h"
#include "../core/test_support.h"

#include "main_window.h"
#include "sample_window.h"

#include "document/reference_video.h"
#include "document/reference_videos.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "panels/reference_video_panel.h"
#include "views/video_view.h"

#include "mocap/base/file_io.h"
#include "mocap/video/reference_video_sidecar.h"

#include <opencv2/videoio.hpp>

#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>

namespace mocap {
namespace {

constexpr int kWidth = 240, kHeight = 136;
constexpr double kCodedVideoRate = 25.0;

void writeCodedVideo(const std::filesystem::path& path, int frames, double rate = kCodedVideoRate)
{
  ASSERT_TRUE(test::writeCodedVideo(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), rate, frames, kWidth, kHeight));
}

QString qPath(const std::filesystem::path& path)
{
  return QString::fromStdString(path.string());
}

/// Waits (processing events, at most 5 s) until the video has delivered `frame`.
bool waitForFrame(const ui::ReferenceVideo& video, Eigen::Index frame)
{
  QElapsedTimer clock;
  clock.start();
  while (video.imageFrame() != frame && clock.elapsed() < 5000)
    QTest::qWait(2);
  return video.imageFrame() == frame;
}

/// The expected video frame at take frame `n` (the sample is 100 Hz): round((n / 100 + offset) · rate).
Eigen::Index expectedFrame(Eigen::Index n, double offset, double rate = kCodedVideoRate)
{
  return static_cast<Eigen::Index>(std::round((static_cast<double>(n) / 100.0 + offset) * rate));
}

/// The studio on a copy of the sample take in `dir` (so its sidecar is written there).
std::unique_ptr<studio::MainWindow> openSampleCopy(const test::TempDir& dir)
{
  auto window = test::openSampleWindow(1280, 800);
  if (!window)
    return nullptr;
  std::filesystem::copy_file(test::sampleTake(), dir.file("take.c3d"));
  const QString error = window->openFile(qPath(dir.file("take.c3d")), true);
  if (!error.isEmpty()) {
    ADD_FAILURE() << error.toStdString();
    return nullptr;
  }
  return window;
}

TEST(ReferenceVideo, ShowsTheExactVideoFrameForEachTakeFrameWithTheOffset)
{
  test::TempDir dir;
  const auto path = dir.file("witness.avi");
  ASSERT_NO_FATAL_FAILURE(writeCodedVideo(path, 400));
  const auto window = openSampleCopy(dir);
  ASSERT_NE(window, nullptr);
  ui::ReferenceVideoPanel* panel = window->referenceVideoPanel();
  ASSERT_NE(panel, nullptr);
  ASSERT_EQ(panel->openVideo(qPath(path)), QString());
  ui::ReferenceVideo& video = panel->video();
  EXPECT_EQ(video.info().frames, 400);
  EXPECT_FALSE(video.info().variableRate);
  video.setOffset(0.52);
  ui::TakeDocument& document = window->document();
  std::vector<Eigen::Index> takeFrames;
  for (Eigen::Index n = 0; n < 60; ++n)
    takeFrames.push_back(n);  // stepping forward
  for (Eigen::Index n = 1200; n > 1100; n -= 7)
    takeFrames.push_back(n);  // a jump, then backwards
  takeFrames.push_back(10);
  takeFrames.push_back(1300);
  for (const Eigen::Index n : takeFrames) {
    document.setCurrentFrame(n);
    const Eigen::Index expected = expectedFrame(n, 0.52);
    ASSERT_EQ(video.wantedFrame(), expected) << n;
    ASSERT_TRUE(waitForFrame(video, expected)) << "take frame " << n << " waits for video frame " << expected;
    EXPECT_EQ(test::codedFrameNumber(video.image()), expected) << "take frame " << n;
  }
  EXPECT_TRUE(panel->view().caption().startsWith(QStringLiteral("video frame")));
  // Idle, the worker decodes ahead: the next video frames are cached, and stepping onto one shows
  // it at once, without waiting for the worker.
  const Eigen::Index shown = video.imageFrame();
  QElapsedTimer clock;
  clock.start();
  while (!video.isCached(shown + 4) && clock.elapsed() < 5000)
    QTest::qWait(5);
  ASSERT_TRUE(video.isCached(shown + 4));
  const Eigen::Index ahead = 1300 + 16;  // (1316/100 + 0.52)·25 = shown + 4
  document.setCurrentFrame(ahead);
  ASSERT_EQ(video.wantedFrame(), shown + 4);
  EXPECT_EQ(video.imageFrame(), shown + 4) << "a cached frame is shown without a round trip to the worker";
  EXPECT_EQ(test::codedFrameNumber(video.image()), shown + 4);
  // Nudging by one video frame moves the offset by 1/25 s.
  video.nudge(1);
  EXPECT_NEAR(video.offset(), 0.56, 1e-12);
  // Past the end of the video: no frame, said so, nothing crashes.
  document.setCurrentFrame(document.take().frameCount() - 1);
  EXPECT_FALSE(video.wantedFrame().has_value());
  EXPECT_EQ(panel->view().caption(), QStringLiteral("No video at this frame"));
  EXPECT_EQ(panel->videoFrameText(), QStringLiteral("none")) << "the box claims no frame the view does not show";
  document.setCurrentFrame(1300);
  EXPECT_EQ(panel->videoFrameText(), QString::number(expectedFrame(1300, 0.56)));
}

TEST(ReferenceVideo, AFileThatIsNotAVideoIsRefusedWithAMessage)
{
  test::TempDir dir;
  const auto path = dir.file("notes.mp4");
  std::FILE* file = std::fopen(path.string().c_str(), "w");
  ASSERT_NE(file, nullptr);
  std::fputs("not a video\n", file);
  std::fclose(file);
  const auto window = openSampleCopy(dir);
  ASSERT_NE(window, nullptr);
  ui::ReferenceVideoPanel* panel = window->referenceVideoPanel();
  ui::ReferenceVideos& linked = window->session().referenceVideos();
  const QString error = panel->openVideo(qPath(path));
  EXPECT_TRUE(error.contains(QStringLiteral("notes.mp4"))) << error.toStdString();
  EXPECT_EQ(linked.count(), 0);
  EXPECT_FALSE(panel->video().isOpen());
  EXPECT_EQ(panel->view().caption(), QStringLiteral("No reference video"));
  // A video file with no frames in it: refused too.
  const auto empty = dir.file("empty.avi");
  {
    cv::VideoWriter writer(empty.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0,
                           cv::Size(kWidth, kHeight));
    ASSERT_TRUE(writer.isOpened());
  }
  EXPECT_TRUE(panel->openVideo(qPath(empty)).contains(QStringLiteral("empty.avi")));
  EXPECT_EQ(linked.count(), 0);
  linked.save();
  EXPECT_FALSE(std::filesystem::exists(referenceVideoSidecarPath(dir.file("take.c3d"))));
}

TEST(ReferenceVideo, SeveralVideosPerTakeEachWithItsOwnOffsetShowTheirFrames)
{
  test::TempDir dir;
  ASSERT_NO_FATAL_FAILURE(writeCodedVideo(dir.file("left.avi"), 600, 25.0));
  ASSERT_NO_FATAL_FAILURE(writeCodedVideo(dir.file("right.avi"), 600, 30.0));
  const auto window = openSampleCopy(dir);
  ASSERT_NE(window, nullptr);
  ui::ReferenceVideoPanel* panel = window->referenceVideoPanel();
  ui::ReferenceVideos& linked = window->session().referenceVideos();
  ASSERT_EQ(panel->openVideo(qPath(dir.file("left.avi"))), QString());
  panel->video().setOffset(0.4);
  ASSERT_EQ(panel->openVideo(qPath(dir.file("right.avi"))), QString());
  panel->video().setOffset(1.1);
  ASSERT_EQ(linked.count(), 2);
  EXPECT_EQ(linked.currentIndex(), 1);
  EXPECT_EQ(panel->openVideo(qPath(dir.file("left.avi"))), QString());  // already linked: shown, not added
  EXPECT_EQ(linked.count(), 2);
  EXPECT_EQ(linked.currentIndex(), 0);
  ui::TakeDocument& document = window->document();
  const std::vector<std::pair<double, double>> videos = {{0.4, 25.0}, {1.1, 30.0}};
  for (const Eigen::Index n : {Eigen::Index{100}, Eigen::Index{900}, Eigen::Index{350}, Eigen::Index{351}}) {
    document.setCurrentFrame(n);
    for (int v = 0; v < 2; ++v) {
      panel->setCurrentIndex(v);
      ui::ReferenceVideo& video = panel->video();
      EXPECT_TRUE(video.isActive());
      EXPECT_FALSE(linked.at(1 - v).isActive()) << "a hidden video decodes nothing";
      const Eigen::Index expected = expectedFrame(n, videos[static_cast<std::size_t>(v)].first,
                                                  videos[static_cast<std::size_t>(v)].second);
      ASSERT_EQ(video.wantedFrame(), expected);
      ASSERT_TRUE(waitForFrame(video, expected)) << "video " << v << " at take frame " << n;
      EXPECT_EQ(test::codedFrameNumber(video.image()), expected);
    }
  }
  panel->removeVideo(0);
  ASSERT_EQ(linked.count(), 1);
  EXPECT_EQ(QFileInfo(panel->video().path()).fileName(), QStringLiteral("right.avi"));
  EXPECT_NEAR(panel->video().offset(), 1.1, 1e-12);
}

TEST(ReferenceVideo, VideosAndOffsetsAreRememberedBesideTheTakeAndAMissingOneIsKept)
{
  test::TempDir dir, elsewhere;
  std::filesystem::create_directories(dir.file("cam"));
  ASSERT_NO_FATAL_FAILURE(writeCodedVideo(dir.file("cam/hmc.avi"), 300));
  ASSERT_NO_FATAL_FAILURE(writeCodedVideo(elsewhere.file("witness.avi"), 300));
  const auto take = dir.file("take.c3d");
  const auto sidecar = referenceVideoSidecarPath(take);
  const auto window = openSampleCopy(dir);
  ASSERT_NE(window, nullptr);
  ui::ReferenceVideoPanel* panel = window->referenceVideoPanel();
  ui::ReferenceVideos& linked = window->session().referenceVideos();
  ASSERT_EQ(panel->openVideo(qPath(dir.file("cam/hmc.avi"))), QString());
  panel->video().setOffset(0.36);
  ASSERT_EQ(panel->openVideo(qPath(elsewhere.file("witness.avi"))), QString());
  panel->video().setOffset(-0.2);
  // Written a moment after the change, without asking.
  QElapsedTimer clock;
  clock.start();
  while (clock.elapsed() < 5000 &&
         (!std::filesystem::exists(sidecar) || readReferenceVideoSidecar(take).size() != 2 ||
          readReferenceVideoSidecar(take)[1].offset != -0.2))
    QTest::qWait(20);
  ASSERT_TRUE(std::filesystem::exists(sidecar));
  EXPECT_NE(readFileBytes(sidecar).find("\"cam/hmc.avi\""), std::string::npos) << "stored relative to the take";

  // Reopening the take restores both, with their offsets, showing their frames.
  ASSERT_EQ(window->openFile(qPath(take), true), QString());
  ASSERT_EQ(linked.count(), 2);
  EXPECT_NEAR(linked.at(0).offset(), 0.36, 1e-12);
  EXPECT_NEAR(linked.at(1).offset(), -0.2, 1e-12);
  EXPECT_FALSE(linked.isMissing(0));
  EXPECT_FALSE(linked.isMissing(1));
  window->document().setCurrentFrame(500);
  panel->setCurrentIndex(1);
  ASSERT_TRUE(waitForFrame(panel->video(), expectedFrame(500, -0.2)));
  EXPECT_EQ(test::codedFrameNumber(panel->video().image()), expectedFrame(500, -0.2));

  // A video moved away: reopening says so, restores the other, and loses nothing from the sidecar.
  const std::string before = readFileBytes(sidecar);
  std::filesystem::rename(elsewhere.file("witness.avi"), elsewhere.file("moved.avi"));
  ASSERT_EQ(window->openFile(qPath(take), true), QString());
  ASSERT_EQ(linked.count(), 2);
  EXPECT_FALSE(linked.isMissing(0));
  EXPECT_TRUE(linked.isMissing(1));
  EXPECT_EQ(linked.currentIndex(), 0) << "the video that is there is shown";
  EXPECT_TRUE(panel->statusText().contains(QStringLiteral("Locate"))) << panel->statusText().toStdString();
  panel->setCurrentIndex(1);
  EXPECT_TRUE(panel->view().caption().contains(QStringLiteral("witness.avi is missing")))
      << panel->view().caption().toStdString();
  linked.save();
  EXPECT_EQ(readFileBytes(sidecar), before) << "declining to locate it keeps it in the sidecar";
  // Changing the other video keeps the missing one as stored.
  panel->setCurrentIndex(0);
  panel->video().setOffset(0.4);
  linked.save();
  auto links = readReferenceVideoSidecar(take);
  ASSERT_EQ(links.size(), 2u);
  EXPECT_DOUBLE_EQ(links[0].offset, 0.4);
  EXPECT_FALSE(links[1].found);
  EXPECT_EQ(links[1].path.filename(), "witness.avi");
  EXPECT_DOUBLE_EQ(links[1].offset, -0.2);

  // Located: it opens with its offset, and the sidecar follows it.
  ASSERT_EQ(panel->locateVideo(1, qPath(elsewhere.file("moved.avi"))), QString());
  EXPECT_FALSE(linked.isMissing(1));
  EXPECT_NEAR(linked.at(1).offset(), -0.2, 1e-12);
  linked.save();
  links = readReferenceVideoSidecar(take);
  ASSERT_EQ(links.size(), 2u);
  EXPECT_TRUE(links[1].found);
  EXPECT_EQ(links[1].path.filename(), "moved.avi");

  // Removing every video removes the sidecar.
  panel->removeVideo(1);
  panel->removeVideo(0);
  linked.save();
  EXPECT_FALSE(std::filesystem::exists(sidecar));
}

TEST(ReferenceVideo, SyncHereLinesTheHeldVideoFrameUpWithTheTakesFrame)
{
  test::TempDir dir;
  ASSERT_NO_FATAL_FAILURE(writeCodedVideo(dir.file("witness.avi"), 400));
  const auto window = openSampleCopy(dir);
  ASSERT_NE(window, nullptr);
  ui::ReferenceVideoPanel* panel = window->referenceVideoPanel();
  ASSERT_EQ(panel->openVideo(qPath(dir.file("witness.avi"))), QString());
  ui::ReferenceVideo& video = panel->video();
  ui::TakeDocument& document = window->document();
  // Held at video frame 40 (a clap, say), the video stays there while the take moves.
  video.hold(40);
  document.setCurrentFrame(120);
  EXPECT_EQ(video.wantedFrame(), Eigen::Index{40});
  document.setCurrentFrame(300);  // the same moment in the take
  EXPECT_EQ(video.wantedFrame(), Eigen::Index{40});
  ASSERT_TRUE(waitForFrame(video, 40));
  EXPECT_TRUE(panel->view().caption().endsWith(QStringLiteral("held")));
  panel->syncHere();
  EXPECT_FALSE(video.heldFrame().has_value());
  EXPECT_NEAR(video.offset(), 40.0 / 25.0 - 3.0, 1e-12);
  EXPECT_EQ(video.wantedFrame(), Eigen::Index{40});
  document.setCurrentFrame(400);  // and it follows the take with the new offset
  EXPECT_EQ(video.wantedFrame(), expectedFrame(400, 40.0 / 25.0 - 3.0));
  ASSERT_TRUE(waitForFrame(video, expectedFrame(400, 40.0 / 25.0 - 3.0)));
  EXPECT_EQ(test::codedFrameNumber(video.image()), 65);
}

TEST(ReferenceVideo, SyncToEventPutsTheVideosFirstFrameAtTheTakesSyncEvent)
{
  test::TempDir dir;
  ASSERT_NO_FATAL_FAILURE(writeCodedVideo(dir.file("witness.avi"), 400));
  const auto window = openSampleCopy(dir);
  ASSERT_NE(window, nullptr);
  ui::TakeDocument& document = window->document();
  Take take = document.take();
  take.events().push_back({"Foot Strike", "Left", "", "", 1.0});
  take.events().push_back({"Sync", "General", "clapper", "", 2.5});
  const std::int64_t first = take.firstFrame();
  document.setTake(std::move(take), qPath(dir.file("take.c3d")));
  ui::ReferenceVideoPanel* panel = window->referenceVideoPanel();
  ASSERT_EQ(panel->openVideo(qPath(dir.file("witness.avi"))), QString());
  ASSERT_EQ(panel->syncEvents().size(), 2u);
  EXPECT_EQ(panel->syncEvents().front(), 1u) << "the sync event is offered first";
  ASSERT_EQ(panel->syncToEvent(panel->syncEvents().front()), QString());
  // Event time 2.5 s counts from the trial's frame 1: take index 250 + 1 − first frame.
  const Eigen::Index eventFrame = 251 - static_cast<Eigen::Index>(first);
  ui::ReferenceVideo& video = panel->video();
  EXPECT_NEAR(video.offset(), -static_cast<double>(eventFrame) / 100.0, 1e-12);
  document.setCurrentFrame(eventFrame);
  EXPECT_EQ(video.wantedFrame(), Eigen::Index{0});
  // With the video held at the moment it shows the clap, that frame goes to the event.
  video.hold(12);
  ASSERT_EQ(panel->syncToEvent(1), QString());
  document.setCurrentFrame(eventFrame);
  EXPECT_EQ(video.wantedFrame(), Eigen::Index{12});
  ASSERT_TRUE(waitForFrame(video, 12));
  EXPECT_EQ(test::codedFrameNumber(video.image()), 12);
}

TEST(ReferenceVideo, AVariableFrameRateVideoIsSaidSoAndShownByItsTimestamps)
{
  test::TempDir dir;
  const auto path = dir.file("phone.mov");
  if (!test::writeVariableRateCodedVideo(path, 25.0, 120, kWidth, kHeight, 60))
    GTEST_SKIP() << "this FFmpeg cannot write MJPEG QuickTime";
  const auto window = openSampleCopy(dir);
  ASSERT_NE(window, nullptr);
  ui::ReferenceVideoPanel* panel = window->referenceVideoPanel();
  ASSERT_EQ(panel->openVideo(qPath(path)), QString());
  ui::ReferenceVideo& video = panel->video();
  // The worker checks the timestamps after opening; the dock then says so.
  QElapsedTimer clock;
  clock.start();
  while (!video.timesChecked() && clock.elapsed() < 5000)
    QTest::qWait(5);
  ASSERT_TRUE(video.timesChecked());
  EXPECT_TRUE(video.info().variableRate);
  // Take frame 320 is 3.2 s: frame 70 by its timestamp ((2·70 − 60) / 25), not 80.
  window->document().setCurrentFrame(320);
  EXPECT_EQ(video.wantedFrame(), Eigen::Index{70});
  ASSERT_TRUE(waitForFrame(video, 70));
  EXPECT_EQ(test::codedFrameNumber(video.image()), 70);
  EXPECT_TRUE(panel->view().caption().contains(QStringLiteral("3.200 s"))) << panel->view().caption().toStdString();
}

} // namespace
} // namespace mocap
