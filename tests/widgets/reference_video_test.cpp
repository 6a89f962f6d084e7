// The Reference Video dock under Xvfb: a video the test writes (each frame shows its number as a
// bar code, at 25 fps against the sample's 100 Hz), stepped through with the take — forward,
// backwards and by jumps — shows exactly the video frame the offset maps each take frame to.
#include "../core/coded_video.h"
#include "../core/test_support.h"

#include "main_window.h"
#include "sample_window.h"

#include "document/reference_video.h"
#include "document/take_document.h"
#include "panels/reference_video_panel.h"
#include "views/video_view.h"

#include <opencv2/videoio.hpp>

#include <QDockWidget>
#include <QElapsedTimer>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>

namespace mocap {
namespace {

constexpr int kWidth = 240, kHeight = 136;
constexpr double kVideoRate = 25.0;

void writeCodedVideo(const std::filesystem::path& path, int frames)
{
  ASSERT_TRUE(test::writeCodedVideo(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), kVideoRate, frames, kWidth, kHeight));
}

Eigen::Index decodeBars(const QImage& image)
{
  return test::codedFrameNumber(image.width(), image.height(),
                                [&](int x, int y) { return qGreen(image.pixel(x, y)) > 128; });
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

TEST(ReferenceVideo, ShowsTheExactVideoFrameForEachTakeFrameWithTheOffset)
{
  test::TempDir dir;
  const auto path = dir.file("witness.avi");
  ASSERT_NO_FATAL_FAILURE(writeCodedVideo(path, 400));
  const auto window = test::openSampleWindow(1280, 800);
  ASSERT_NE(window, nullptr);
  ui::ReferenceVideoPanel* panel = window->referenceVideoPanel();
  ASSERT_NE(panel, nullptr);
  ASSERT_EQ(panel->openVideo(QString::fromStdString(path.string())), QString());
  ui::ReferenceVideo& video = panel->video();
  EXPECT_EQ(video.info().frames, 400);
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
    const auto expected = static_cast<Eigen::Index>(std::round((static_cast<double>(n) / 100.0 + 0.52) * kVideoRate));
    ASSERT_EQ(video.wantedFrame(), expected) << n;
    ASSERT_TRUE(waitForFrame(video, expected)) << "take frame " << n << " waits for video frame " << expected;
    EXPECT_EQ(decodeBars(video.image()), expected) << "take frame " << n;
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
  EXPECT_EQ(decodeBars(video.image()), shown + 4);
  // Nudging by one video frame moves the offset by 1/25 s.
  video.nudge(1);
  EXPECT_NEAR(video.offset(), 0.56, 1e-12);
  // Past the end of the video: no frame, said so, nothing crashes.
  document.setCurrentFrame(document.take().frameCount() - 1);
  EXPECT_FALSE(video.wantedFrame().has_value());
  EXPECT_EQ(panel->view().caption(), QStringLiteral("No video at this frame"));
}

TEST(ReferenceVideo, AFileThatIsNotAVideoIsRefusedWithAMessage)
{
  test::TempDir dir;
  const auto path = dir.file("notes.mp4");
  std::FILE* file = std::fopen(path.string().c_str(), "w");
  ASSERT_NE(file, nullptr);
  std::fputs("not a video\n", file);
  std::fclose(file);
  const auto window = test::openSampleWindow(1280, 800);
  ASSERT_NE(window, nullptr);
  ui::ReferenceVideoPanel* panel = window->referenceVideoPanel();
  const QString error = panel->openVideo(QString::fromStdString(path.string()));
  EXPECT_TRUE(error.contains(QStringLiteral("notes.mp4"))) << error.toStdString();
  EXPECT_FALSE(panel->video().isOpen());
  EXPECT_EQ(panel->view().caption(), QStringLiteral("No reference video"));
}

} // namespace
} // namespace mocap
