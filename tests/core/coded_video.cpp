#include "coded_video.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

namespace mocap::test {

bool writeCodedVideo(const std::filesystem::path& path, int fourcc, double rate, int frames, int width, int height)
{
  cv::VideoWriter writer(path.string(), cv::CAP_FFMPEG, fourcc, rate, cv::Size(width, height));
  if (!writer.isOpened())
    return false;
  const int bar = width / kCodedBits;
  for (int f = 0; f < frames; ++f) {
    cv::Mat image(height, width, CV_8UC3, cv::Scalar(0, 0, 0));
    for (int b = 0; b < kCodedBits; ++b)
      if ((f >> (kCodedBits - 1 - b)) & 1)
        cv::rectangle(image, cv::Rect(b * bar, 0, bar, height), cv::Scalar(255, 255, 255), cv::FILLED);
    writer.write(image);
  }
  return true;
}

Eigen::Index codedFrameNumber(int width, int height, const std::function<bool(int, int)>& whiteAt)
{
  const int bar = width / kCodedBits;
  Eigen::Index value = 0;
  for (int b = 0; b < kCodedBits; ++b)
    value = 2 * value + (whiteAt(b * bar + bar / 2, height / 2) ? 1 : 0);
  return value;
}

} // namespace mocap::test
