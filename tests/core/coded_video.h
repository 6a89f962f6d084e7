#pragma once

#include "mocap/video/video_source.h"

#include <Eigen/Core>

#include <filesystem>
#include <functional>

namespace mocap::test {

/// Bar codes of frame numbers: each frame of a test video shows its own index as 12 vertical
/// bars (white = 1, most significant first), which survive MJPEG and H.264 compression.
constexpr int kCodedBits = 12;

/// One frame showing the number `frame` as bars, RGB (white bars on black).
[[nodiscard]] VideoImage codedImage(Eigen::Index frame, int width, int height);

/// Writes `frames` frames of `width` × `height` at `rate` with OpenCV, each showing its number.
/// False when this FFmpeg cannot encode `fourcc`.
bool writeCodedVideo(const std::filesystem::path& path, int fourcc, double rate, int frames, int width, int height);

/// writeCodedVideo as an MJPEG QuickTime file (.mov) whose frames from `slowFrom` on last two
/// frame intervals each (a variable frame rate: frame i ≥ slowFrom is at (2i − slowFrom) / rate):
/// written at a constant rate with OpenCV, then its sample-time table ('stts') and durations are
/// rewritten. False when this FFmpeg cannot write it or the file is not laid out as expected.
bool writeVariableRateCodedVideo(const std::filesystem::path& path, double rate, int frames, int width, int height,
                                 int slowFrom);

/// The number a decoded frame's bars spell, read across its middle row; `whiteAt(x, y)` says
/// whether the pixel there is light.
[[nodiscard]] Eigen::Index codedFrameNumber(int width, int height, const std::function<bool(int, int)>& whiteAt);

/// The number a decoded RGB frame's bars spell, read on its green channel.
[[nodiscard]] Eigen::Index codedFrameNumber(const VideoImage& image);

} // namespace mocap::test
