#include "mocap/video/review_frame.h"

#include "mocap/base/error.h"
#include "mocap/base/number_text.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace mocap {

namespace {

constexpr int kMinimumSide = 64;

cv::Mat wrap(const VideoImage& image)
{
  // OpenCV only reads through this header; the cast keeps the image's own buffer.
  return {image.height, image.width, CV_8UC3, const_cast<std::uint8_t*>(image.rgb.data())};
}

cv::Rect rect(const PixelRect& r)
{
  return {r.x, r.y, r.width, r.height};
}

/// `source` scaled to fit inside `area` with its aspect kept, centred (black bars around).
void letterbox(const cv::Mat& source, cv::Mat area)
{
  const double scale = std::min(static_cast<double>(area.cols) / source.cols, static_cast<double>(area.rows) / source.rows);
  const int width = std::max(1, static_cast<int>(std::lround(source.cols * scale)));
  const int height = std::max(1, static_cast<int>(std::lround(source.rows * scale)));
  cv::Mat target = area(cv::Rect((area.cols - width) / 2, (area.rows - height) / 2, width, height));
  cv::resize(source, target, target.size(), 0, 0, scale < 1.0 ? cv::INTER_AREA : cv::INTER_LINEAR);
}

/// `text` in white on the band, vertically centred, starting at `x` or ending at the band's right
/// edge minus `x` when `alignRight`.
void putCaption(cv::Mat band, const std::string& text, int x, bool alignRight)
{
  if (text.empty())
    return;
  const double scale = band.rows / 40.0;
  const int thickness = std::max(1, static_cast<int>(std::lround(band.rows / 20.0)));
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, thickness, &baseline);
  const int left = alignRight ? band.cols - x - size.width : x;
  const cv::Point origin(std::max(0, left), (band.rows + size.height) / 2);
  cv::putText(band, text, origin, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(235, 235, 235), thickness, cv::LINE_AA);
}

} // namespace

ReviewLayout reviewLayout(int width, int height, bool withVideo)
{
  if (width < kMinimumSide || height < kMinimumSide)
    throw InvalidArgument("review video: " + std::to_string(width) + " x " + std::to_string(height) +
                          " is too small (at least " + std::to_string(kMinimumSide) + " x " +
                          std::to_string(kMinimumSide) + ")");
  const int captionHeight = std::max(20, static_cast<int>(std::lround(height * 0.05)) / 2 * 2);
  const int top = height - captionHeight;
  ReviewLayout layout;
  layout.caption = {0, top, width, captionHeight};
  const int viewWidth = withVideo ? width / 2 / 2 * 2 : width;  // even: encoders and GL like it
  layout.view = {0, 0, viewWidth, top};
  if (withVideo)
    layout.video = {viewWidth, 0, width - viewWidth, top};
  return layout;
}

std::string reviewTimeText(long long firstFrame, long long frame, double rate)
{
  return "frame " + std::to_string(firstFrame + frame) + "  " + timecodeText(static_cast<double>(frame) / rate, rate);
}

VideoImage composeReviewFrame(const ReviewLayout& layout, const VideoImage& view, const VideoImage* video,
                              const ReviewCaption& caption)
{
  if (view.width <= 0 || view.height <= 0 || view.rgb.size() != VideoImage::byteCount(view.width, view.height))
    throw InvalidArgument("review video: the view image has no pixels");
  VideoImage out;
  out.width = layout.caption.width;
  out.height = layout.caption.y + layout.caption.height;
  out.rgb.assign(VideoImage::byteCount(out.width, out.height), 0);
  cv::Mat frame(out.height, out.width, CV_8UC3, out.rgb.data());

  cv::Mat viewArea = frame(rect(layout.view));
  const cv::Mat source = wrap(view);
  if (source.size() == viewArea.size())
    source.copyTo(viewArea);
  else
    cv::resize(source, viewArea, viewArea.size(), 0, 0, cv::INTER_AREA);

  if (layout.video.width > 0) {
    cv::Mat videoArea = frame(rect(layout.video));
    if (video && video->width > 0 && video->height > 0)
      letterbox(wrap(*video), videoArea);
    else
      putCaption(videoArea(cv::Rect(0, videoArea.rows / 2 - layout.caption.height / 2, videoArea.cols, layout.caption.height)),
                 caption.videoNote, layout.caption.height / 2, false);
  }

  cv::Mat band = frame(rect(layout.caption));
  band.setTo(cv::Scalar(24, 24, 24));
  putCaption(band, caption.take, layout.caption.height / 2, false);
  putCaption(band, caption.time, layout.caption.height / 2, true);
  return out;
}

} // namespace mocap
