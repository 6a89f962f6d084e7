// Reference video: the take ↔ video frame mapping, and frame-exact decoding of videos the test
// makes itself with OpenCV — each frame shows its own number as a bar code — read back in order,
// backwards and by jumps, as MJPEG AVI and (where FFmpeg has an H.264 encoder) MP4.
#include "coded_video.h"
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/model/take.h"
#include "mocap/video/video_source.h"
#include "mocap/video/video_sync.h"

#include <opencv2/videoio.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

namespace mocap {
namespace {

constexpr int kWidth = 320, kHeight = 240;

bool writeCodedVideo(const std::filesystem::path& path, int fourcc, double rate, int frames)
{
  return test::writeCodedVideo(path, fourcc, rate, frames, kWidth, kHeight);
}

/// Reads `order` and expects each decoded frame to be the one asked for.
void expectExactFrames(VideoSource& video, const std::vector<Eigen::Index>& order)
{
  for (const Eigen::Index f : order) {
    const VideoImage image = video.frame(f);
    ASSERT_EQ(image.frame, f);
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);
    EXPECT_EQ(test::codedFrameNumber(image), f) << "asked for frame " << f;
  }
}

// Steps, short skips ahead (decoded on), long jumps and steps back (seeks).
const std::vector<Eigen::Index> kOrder = {0, 1, 2, 3, 100, 101, 4, 149, 148, 147, 50, 51, 52, 10, 0, 120, 119, 60, 75, 110, 111, 140};

TEST(VideoSync, MapsTakeFramesToVideoFramesWithTheOffset)
{
  const VideoSync sync{100.0, 24.0, 0.37};
  for (Eigen::Index n = 0; n < 500; ++n) {
    const double expected = std::round((static_cast<double>(n) / 100.0 + 0.37) * 24.0);
    const auto frame = videoFrameAt(sync, n, 1000);
    ASSERT_TRUE(frame.has_value());
    EXPECT_EQ(*frame, static_cast<Eigen::Index>(expected)) << n;
  }
  EXPECT_FALSE(videoFrameAt(sync, 0, 5).has_value());       // video frame 9 of a 5-frame video
  EXPECT_FALSE(videoFrameAt({100.0, 24.0, -1.0}, 0, 1000).has_value());  // before the video starts
  EXPECT_EQ(videoFrameAt({100.0, 24.0, -1.0}, 100, 1000), Eigen::Index{0});
  // The offset that puts video frame 40 at take frame 250 does so.
  VideoSync matched = sync;
  matched.offset = offsetMatching(sync, 250, 40);
  EXPECT_EQ(videoFrameAt(matched, 250, 1000), Eigen::Index{40});
  EXPECT_THROW((void)videoFrameAt({0.0, 24.0, 0.0}, 0, 10), InvalidArgument);
  EXPECT_THROW((void)videoFrameAt({100.0, -1.0, 0.0}, 0, 10), InvalidArgument);
  EXPECT_THROW((void)videoFrameAt({100.0, 24.0, std::nan("")}, 0, 10), InvalidArgument);
}

TEST(VideoSource, DecodesEveryFrameExactlyInOrderBackwardsAndByJumps)
{
  test::TempDir dir;
  const auto path = dir.file("coded.avi");
  ASSERT_TRUE(writeCodedVideo(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 24.0, 150));
  VideoSource video(path);
  EXPECT_EQ(video.info().frames, 150);
  EXPECT_DOUBLE_EQ(video.info().rate, 24.0);
  EXPECT_EQ(video.info().width, kWidth);
  EXPECT_EQ(video.info().codec, "MJPG");
  EXPECT_NEAR(video.info().seconds(), 6.25, 1e-9);
  EXPECT_FALSE(video.info().variableRate);
  EXPECT_TRUE(video.info().frameTimes.empty());
  expectExactFrames(video, kOrder);
}

TEST(VideoSource, H264SeeksLandOnTheExactFrame)
{
  test::TempDir dir;
  const auto path = dir.file("coded.mp4");
  if (!writeCodedVideo(path, cv::VideoWriter::fourcc('a', 'v', 'c', '1'), 30.0, 150))
    GTEST_SKIP() << "this FFmpeg has no H.264 encoder";
  VideoSource video(path);
  EXPECT_EQ(video.info().frames, 150);
  EXPECT_DOUBLE_EQ(video.info().rate, 30.0);
  expectExactFrames(video, kOrder);
}

TEST(VideoSource, ATakeSteppedWithAnOffsetShowsTheMatchingVideoFrames)
{
  test::TempDir dir;
  const auto path = dir.file("witness.avi");
  ASSERT_TRUE(writeCodedVideo(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0, 200));
  VideoSource video(path);
  const VideoSync sync{100.0, video.info().rate, 0.52};
  // Forward steps, a jump back and single steps backwards, as a technician scrubs.
  std::vector<Eigen::Index> takeFrames;
  for (Eigen::Index n = 0; n < 120; ++n)
    takeFrames.push_back(n);
  for (Eigen::Index n = 300; n > 200; n -= 3)
    takeFrames.push_back(n);
  for (const Eigen::Index n : takeFrames) {
    const auto frame = videoFrameAt(sync, n, video.info().frames);
    ASSERT_TRUE(frame.has_value()) << n;
    EXPECT_EQ(*frame, static_cast<Eigen::Index>(std::round((static_cast<double>(n) / 100.0 + 0.52) * 25.0)));
    EXPECT_EQ(test::codedFrameNumber(video.frame(*frame)), *frame) << "take frame " << n;
  }
}

TEST(VideoSource, BadFilesAndFramesGiveClearErrors)
{
  test::TempDir dir;
  EXPECT_THROW(VideoSource(dir.file("missing.mp4")), IoError);
  std::ofstream(dir.file("text.mp4")) << "not a video at all\n";
  EXPECT_THROW(VideoSource(dir.file("text.mp4")), Error);
  const auto path = dir.file("short.avi");
  ASSERT_TRUE(writeCodedVideo(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 24.0, 5));
  VideoSource video(path);
  EXPECT_THROW((void)video.frame(5), InvalidArgument);
  EXPECT_THROW((void)video.frame(-1), InvalidArgument);
  EXPECT_EQ(test::codedFrameNumber(video.frame(4)), 4);  // still usable after the refusals
  // A video file with no frames in it: refused, the file named.
  const auto empty = dir.file("empty.avi");
  {
    cv::VideoWriter writer(empty.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 24.0,
                           cv::Size(kWidth, kHeight));
    ASSERT_TRUE(writer.isOpened());
  }
  try {
    VideoSource none(empty);
    ADD_FAILURE() << "a video with no frames opened";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("empty.avi"), std::string::npos) << e.what();
  }
}

TEST(VideoSync, MapsByTimestampsForAVariableFrameRate)
{
  const std::vector<double> times = {0.0, 0.04, 0.08, 0.16, 0.24, 0.5};
  const VideoSync sync{100.0, 25.0, 0.0};
  EXPECT_EQ(videoFrameAt(sync, 0, times), Eigen::Index{0});
  EXPECT_EQ(videoFrameAt(sync, 11, times), Eigen::Index{2});   // 0.11 s: 0.08 s is nearer than 0.16 s
  EXPECT_EQ(videoFrameAt(sync, 20, times), Eigen::Index{4});   // a tie (0.16 / 0.24) goes to the later frame
  EXPECT_EQ(videoFrameAt(sync, 40, times), Eigen::Index{5});
  EXPECT_EQ(videoFrameAt(sync, 62, times), Eigen::Index{5});   // within half the last interval (0.13 s)
  EXPECT_FALSE(videoFrameAt(sync, 64, times).has_value());     // past it
  EXPECT_FALSE(videoFrameAt({100.0, 25.0, -0.03}, 0, times).has_value());  // before the first frame's half
  EXPECT_FALSE(videoFrameAt(sync, 0, std::vector<double>{}).has_value());
  // Regular times agree with the constant-rate mapping.
  std::vector<double> regular;
  for (int i = 0; i < 200; ++i)
    regular.push_back(i / 25.0);
  for (Eigen::Index n = 0; n < 900; ++n)
    EXPECT_EQ(videoFrameAt({100.0, 25.0, 0.371}, n, regular), videoFrameAt({100.0, 25.0, 0.371}, n, 200)) << n;
  const double offset = offsetMatching(sync, 30, 4, times);
  EXPECT_DOUBLE_EQ(offset, 0.24 - 0.30);
  EXPECT_EQ(videoFrameAt({100.0, 25.0, offset}, 30, times), Eigen::Index{4});
  EXPECT_THROW((void)offsetMatching(sync, 30, 6, times), InvalidArgument);
}

TEST(VideoSync, FindsTheTakesSyncEventAndItsFrame)
{
  std::vector<Event> events = {{"Foot Strike", "Left", "", "", 1.0}, {"Start", "General", "", "", 0.5}};
  EXPECT_EQ(syncEventIndex(events), std::size_t{1});
  events.push_back({"Camera", "General", "TTL sync pulse", "", 2.0});  // named in the description
  EXPECT_EQ(syncEventIndex(events), std::size_t{2}) << "sync is preferred to start";
  EXPECT_FALSE(syncEventIndex({{"Foot Off", "Right", "", "", 1.0}}).has_value());
  EXPECT_FALSE(syncEventIndex({}).has_value());
  // Event times count from the trial's frame 1.
  EXPECT_EQ(takeFrameOfEvent(0.0, 100.0, 1), 0);
  EXPECT_EQ(takeFrameOfEvent(2.5, 100.0, 1), 250);
  EXPECT_EQ(takeFrameOfEvent(2.5, 100.0, 201), 50);  // a take trimmed to start at frame 201
  EXPECT_EQ(takeFrameOfEvent(0.1249, 120.0, 1), 15);
}

TEST(VideoSource, AVariableFrameRateFileIsSaidSoAndMappedByItsTimestamps)
{
  test::TempDir dir;
  const auto path = dir.file("phone.mov");
  constexpr int kFrames = 120, kSlowFrom = 60;
  if (!test::writeVariableRateCodedVideo(path, 25.0, kFrames, kWidth, kHeight, kSlowFrom))
    GTEST_SKIP() << "this FFmpeg cannot write MJPEG QuickTime";
  VideoSource video(path);
  const VideoInfo& info = video.info();
  EXPECT_TRUE(info.variableRate);
  ASSERT_EQ(info.frames, kFrames);
  ASSERT_EQ(info.frameTimes.size(), static_cast<std::size_t>(kFrames));
  for (int i = 0; i < kFrames; ++i) {
    const double expected = (i < kSlowFrom ? i : 2 * i - kSlowFrom) / 25.0;
    EXPECT_NEAR(info.frameTimes[static_cast<std::size_t>(i)], expected, 1e-3) << i;
  }
  EXPECT_NEAR(info.seconds(), (2 * kFrames - kSlowFrom) / 25.0, 1e-3);
  // Exact frames also when seeking, which goes by timestamp here.
  expectExactFrames(video, {0, 1, 2, 100, 101, 59, 60, 61, 119, 118, 117, 30, 90, 5, 110, 61, 60, 59});
  // Take time 3.2 s is frame 70 by its timestamp ((2·70 − 60) / 25), not frame 80 as the first
  // frames' 25 fps says, nor what the average rate (FFmpeg's nominal one here) says.
  const VideoSync sync{100.0, info.rate, 0.3};
  EXPECT_EQ(videoFrameAt(sync, 290, info.frameTimes), Eigen::Index{70});
  EXPECT_EQ(videoFrameAt({100.0, 25.0, 0.3}, 290, info.frames), Eigen::Index{80});
  EXPECT_NE(videoFrameAt(sync, 290, info.frames), Eigen::Index{70});
  EXPECT_EQ(test::codedFrameNumber(video.frame(70)), 70);
}

} // namespace
} // namespace mocap
