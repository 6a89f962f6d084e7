// Reference video: the take ↔ video frame mapping, and frame-exact decoding of videos the test
// makes itself with OpenCV — each frame shows its own number as a bar code — read back in order,
// backwards and by jumps, as MJPEG AVI and (where FFmpeg has an H.264 encoder) MP4.
#include "coded_video.h"
#include "test_support.h"

#include "mocap/base/error.h"
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

Eigen::Index decodeBars(const VideoImage& image)
{
  return test::codedFrameNumber(image.width, image.height, [&](int x, int y) {
    const std::size_t at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) * 3;
    return image.rgb[at + 1] > 128;
  });
}

/// Reads `order` and expects each decoded frame to be the one asked for.
void expectExactFrames(VideoSource& video, const std::vector<Eigen::Index>& order)
{
  for (const Eigen::Index f : order) {
    const VideoImage image = video.frame(f);
    ASSERT_EQ(image.frame, f);
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);
    EXPECT_EQ(decodeBars(image), f) << "asked for frame " << f;
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
    EXPECT_EQ(decodeBars(video.frame(*frame)), *frame) << "take frame " << n;
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
  EXPECT_EQ(decodeBars(video.frame(4)), 4);  // still usable after the refusals
}

} // namespace
} // namespace mocap
