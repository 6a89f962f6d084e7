#pragma once

#include "mocap/video/video_source.h"

#include <string>

namespace mocap {

/// A rectangle of a review frame, in pixels from the top-left corner.
struct PixelRect
{
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
};

/// Where the parts of a review frame go: the 3D view, the reference video beside it (on the right
/// half, when there is one; the view then takes the left half) and a caption band along the bottom
/// (about 5 % of the height, at least 20 pixels).
struct ReviewLayout
{
  PixelRect view;
  PixelRect video;  ///< empty without a reference video
  PixelRect caption;
};

/// The layout of a `width` × `height` review frame. Throws InvalidArgument for a size too small to
/// hold a view and a caption (under 64 × 64). O(1).
[[nodiscard]] ReviewLayout reviewLayout(int width, int height, bool withVideo);

/// The text burnt into one review frame: the take's name on the left, the frame number and timecode
/// on the right, and a note in the video's half (e.g. "no video at this frame").
struct ReviewCaption
{
  std::string take;
  std::string time;
  std::string videoNote;
};

/// The caption's right-hand text for take frame `frame` (0-based) numbered from `firstFrame` at
/// `rate` Hz: "frame 1234  00:00:12:34.000". O(1).
[[nodiscard]] std::string reviewTimeText(long long firstFrame, long long frame, double rate);

/// One review frame of `layout`'s size: `view` (scaled to the view rectangle when its size
/// differs), `video` letterboxed into the video rectangle when the layout has one (black, with the
/// note, when `video` is empty), and the caption band. Throws InvalidArgument for a view image
/// with no pixels. O(width · height).
[[nodiscard]] VideoImage composeReviewFrame(const ReviewLayout& layout, const VideoImage& view, const VideoImage* video,
                                            const ReviewCaption& caption);

} // namespace mocap
