// Review videos: the frame layout and caption, and the writer — frames read back with OpenCV in
// order and count, at the size and rate asked for, MP4 when an encoder exists (else the MJPEG
// AVI fallback), and never a partial file when an export is abandoned or fails.
#include "coded_video.h"
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/video/review_frame.h"
#include "mocap/video/review_video_writer.h"
#include "mocap/video/video_source.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace mocap {
namespace {

constexpr int kVideoWidth = 320, kVideoHeight = 240;

std::size_t pixelAt(const VideoImage& image, int x, int y)
{
  return (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) * 3;
}

/// Files in `folder` (the writer's temporary files start with a dot).
std::vector<std::string> filesIn(const std::filesystem::path& folder)
{
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(ReviewLayout, PutsTheViewLeftTheVideoRightAndTheCaptionBelow)
{
  const ReviewLayout alone = reviewLayout(1280, 720, false);
  EXPECT_EQ(alone.view.width, 1280);
  EXPECT_EQ(alone.caption.y, alone.view.height);
  EXPECT_EQ(alone.caption.y + alone.caption.height, 720);
  EXPECT_GE(alone.caption.height, 20);
  EXPECT_EQ(alone.video.width, 0);

  const ReviewLayout both = reviewLayout(1280, 720, true);
  EXPECT_EQ(both.view.width, 640);
  EXPECT_EQ(both.video.x, 640);
  EXPECT_EQ(both.video.width, 640);
  EXPECT_EQ(both.video.height, both.view.height);
  EXPECT_EQ(both.view.height % 2, 0);
  EXPECT_THROW((void)reviewLayout(32, 720, false), InvalidArgument);
}

TEST(ReviewFrame, ComposesTheViewTheLetterboxedVideoAndACaption)
{
  const ReviewLayout layout = reviewLayout(kVideoWidth * 2, kVideoHeight, true);
  const VideoImage view = test::codedImage(5, layout.view.width, layout.view.height);
  const VideoImage video = test::codedImage(9, 160, 90);  // wider than its half: bars above and below
  const VideoImage frame = composeReviewFrame(layout, view, &video, {"Facial-Sing", "frame 7  00:00:00:07.000", ""});
  ASSERT_EQ(frame.width, kVideoWidth * 2);
  ASSERT_EQ(frame.height, kVideoHeight);
  // The view half is the view, unscaled.
  for (int y = 0; y < layout.view.height; y += 7)
    for (int x = 0; x < layout.view.width; x += 5)
      ASSERT_EQ(frame.rgb[pixelAt(frame, x, y)], view.rgb[pixelAt(view, x, y)]) << x << "," << y;
  // The video half shows the video's number, and the letterbox is black above it.
  VideoImage half;
  half.width = layout.video.width;
  half.height = layout.video.height;
  half.rgb.resize(VideoImage::byteCount(half.width, half.height));
  for (int y = 0; y < half.height; ++y)
    std::copy_n(frame.rgb.begin() + static_cast<std::ptrdiff_t>(pixelAt(frame, layout.video.x, y)), half.width * 3,
                half.rgb.begin() + static_cast<std::ptrdiff_t>(pixelAt(half, 0, y)));
  EXPECT_EQ(test::codedFrameNumber(half), 9);
  EXPECT_EQ(frame.rgb[pixelAt(frame, layout.video.x + half.width - 2, 2)], 0);
  // The caption band is dark with light text on it.
  int light = 0, dark = 0;
  for (int y = layout.caption.y; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x)
      (frame.rgb[pixelAt(frame, x, y)] > 150 ? light : dark) += 1;
  EXPECT_GT(light, 100) << "text was drawn";
  EXPECT_GT(dark, 10 * light) << "on a dark band";
}

TEST(ReviewFrame, SaysWhenThereIsNoVideoAtAFrame)
{
  const ReviewLayout layout = reviewLayout(kVideoWidth * 2, kVideoHeight, true);
  const VideoImage view = test::codedImage(1, layout.view.width, layout.view.height);
  const VideoImage silent = composeReviewFrame(layout, view, nullptr, {"take", "frame 1", ""});
  const VideoImage noted = composeReviewFrame(layout, view, nullptr, {"take", "frame 1", "no video at this frame"});
  int lightSilent = 0, lightNoted = 0;
  for (int y = 0; y < layout.video.height; ++y)
    for (int x = layout.video.x; x < kVideoWidth * 2; ++x) {
      lightSilent += silent.rgb[pixelAt(silent, x, y)] > 150 ? 1 : 0;
      lightNoted += noted.rgb[pixelAt(noted, x, y)] > 150 ? 1 : 0;
    }
  EXPECT_EQ(lightSilent, 0);
  EXPECT_GT(lightNoted, 50);
}

TEST(ReviewTime, NumbersTheFrameAsTheTakeDoesWithATimecode)
{
  EXPECT_EQ(reviewTimeText(100, 0, 100.0), "frame 100  00:00:00:00.000");
  EXPECT_EQ(reviewTimeText(1, 6125, 100.0), "frame 6126  00:01:01:25.000");
}

/// Writes `frames` coded frames and reads them back.
void expectRoundTrip(const std::filesystem::path& path, double rate, int frames)
{
  ReviewEncoding encoding;
  {
    ReviewVideoWriter writer(path, kVideoWidth, kVideoHeight, rate);
    for (int f = 0; f < frames; ++f)
      writer.write(test::codedImage(f, kVideoWidth, kVideoHeight));
    encoding = writer.encoding();
    EXPECT_FALSE(std::filesystem::exists(encoding.path)) << "nothing in place before finish";
    writer.finish();
  }
  ASSERT_TRUE(std::filesystem::exists(encoding.path));
  VideoSource video(encoding.path);
  EXPECT_EQ(video.info().frames, frames);
  EXPECT_EQ(video.info().width, kVideoWidth);
  EXPECT_EQ(video.info().height, kVideoHeight);
  EXPECT_NEAR(video.info().rate, rate, 1e-3);
  for (int f = 0; f < frames; ++f)
    ASSERT_EQ(test::codedFrameNumber(video.frame(f)), f) << encoding.codec << " frame " << f;
  EXPECT_EQ(filesIn(path.parent_path()), std::vector<std::string>{encoding.path.filename().string()});
}

TEST(ReviewVideoWriter, WritesMp4OrSaysItFellBackToMjpegAvi)
{
  const test::TempDir dir;
  const std::filesystem::path& folder = dir.path();
  const std::filesystem::path path = folder / "review.mp4";
  ReviewEncoding encoding;
  {
    ReviewVideoWriter writer(path, kVideoWidth, kVideoHeight, 60.0);
    encoding = writer.encoding();
  }
  if (encoding.container == "mp4") {
    EXPECT_EQ(encoding.path, path);
    EXPECT_TRUE(encoding.codec == "avc1" || encoding.codec == "mp4v") << encoding.codec;
  } else {
    EXPECT_EQ(encoding.path, folder / "review.avi");
    EXPECT_EQ(encoding.codec, "MJPG");
  }
  std::cout << "review video encoder here: " << encoding.codec << " in " << encoding.container << '\n';
  expectRoundTrip(path, 60.0, 40);
}

TEST(ReviewVideoWriter, WritesMjpegAviFrameExact)
{
  const test::TempDir dir;
  const std::filesystem::path& folder = dir.path();
  expectRoundTrip(folder / "review.avi", 25.0, 30);
}

TEST(ReviewVideoWriter, LeavesNoFileWhenAbandonedOrEmpty)
{
  const test::TempDir dir;
  const std::filesystem::path& folder = dir.path();
  {
    ReviewVideoWriter writer(folder / "cancelled.avi", kVideoWidth, kVideoHeight, 30.0);
    for (int f = 0; f < 5; ++f)
      writer.write(test::codedImage(f, kVideoWidth, kVideoHeight));
  }  // cancelled: destroyed without finish
  {
    ReviewVideoWriter writer(folder / "empty.avi", kVideoWidth, kVideoHeight, 30.0);
    EXPECT_THROW(writer.finish(), IoError);
  }
  EXPECT_TRUE(filesIn(folder).empty());
  // An existing file is replaced only by a finished video.
  const std::filesystem::path kept = folder / "kept.avi";
  {
    ReviewVideoWriter writer(kept, kVideoWidth, kVideoHeight, 30.0);
    writer.write(test::codedImage(3, kVideoWidth, kVideoHeight));
    writer.finish();
  }
  const auto size = std::filesystem::file_size(kept);
  {
    ReviewVideoWriter writer(kept, kVideoWidth, kVideoHeight, 30.0);
    for (int f = 0; f < 20; ++f)
      writer.write(test::codedImage(f, kVideoWidth, kVideoHeight));
  }
  EXPECT_EQ(std::filesystem::file_size(kept), size);
  EXPECT_EQ(filesIn(folder), std::vector<std::string>{"kept.avi"});
}

TEST(ReviewVideoWriter, RefusesBadSizesFramesAndFolders)
{
  const test::TempDir dir;
  const std::filesystem::path& folder = dir.path();
  EXPECT_THROW(ReviewVideoWriter(folder / "odd.avi", 321, 240, 30.0), InvalidArgument);
  EXPECT_THROW(ReviewVideoWriter(folder / "zero.avi", 0, 240, 30.0), InvalidArgument);
  EXPECT_THROW(ReviewVideoWriter(folder / "rate.avi", kVideoWidth, kVideoHeight, 0.0), InvalidArgument);
  EXPECT_THROW(ReviewVideoWriter(folder / "no" / "such" / "folder.avi", kVideoWidth, kVideoHeight, 30.0), IoError);
  ReviewVideoWriter writer(folder / "size.avi", kVideoWidth, kVideoHeight, 30.0);
  EXPECT_THROW(writer.write(test::codedImage(0, kVideoWidth / 2, kVideoHeight)), InvalidArgument);
}

} // namespace
} // namespace mocap
