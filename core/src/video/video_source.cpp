#include "mocap/video/video_source.h"

#include "mocap/base/error.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <cmath>
#include <cstring>

namespace mocap {

struct VideoSource::Decoder
{
  cv::VideoCapture capture;
  Eigen::Index next = 0;  // the frame the next read() returns
  cv::Mat bgr;
};

namespace {

/// Forward jumps up to this many frames decode on instead of seeking (a seek decodes from the key
/// frame before the target, which may be hundreds of frames back).
constexpr Eigen::Index kSkipAhead = 48;

std::string fourcc(double code)
{
  const auto value = static_cast<std::uint32_t>(code);
  std::string text;
  for (int i = 0; i < 4; ++i) {
    const char c = static_cast<char>((value >> (8 * i)) & 0xFF);
    if (c > ' ' && c < 127)
      text += c;
  }
  return text;
}

} // namespace

VideoSource::VideoSource(const std::filesystem::path& path) : m_decoder(std::make_unique<Decoder>()), m_path(path)
{
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw IoError(path.string() + ": no such video file");
  if (!m_decoder->capture.open(path.string(), cv::CAP_FFMPEG) || !m_decoder->capture.isOpened())
    throw IoError(path.string() + ": not a video this build can decode");
  cv::VideoCapture& capture = m_decoder->capture;
  m_info.frames = static_cast<Eigen::Index>(std::llround(capture.get(cv::CAP_PROP_FRAME_COUNT)));
  m_info.rate = capture.get(cv::CAP_PROP_FPS);
  m_info.width = static_cast<int>(capture.get(cv::CAP_PROP_FRAME_WIDTH));
  m_info.height = static_cast<int>(capture.get(cv::CAP_PROP_FRAME_HEIGHT));
  m_info.codec = fourcc(capture.get(cv::CAP_PROP_FOURCC));
  if (!(m_info.rate > 0.0) || !std::isfinite(m_info.rate))
    throw FormatError(path.string(), "the video has no frame rate");
  if (m_info.frames <= 0 || m_info.width <= 0 || m_info.height <= 0)
    throw FormatError(path.string(), "the video has no frames");
}

VideoSource::~VideoSource() = default;
VideoSource::VideoSource(VideoSource&&) noexcept = default;
VideoSource& VideoSource::operator=(VideoSource&&) noexcept = default;

VideoImage VideoSource::frame(Eigen::Index index)
{
  if (index < 0 || index >= m_info.frames)
    throw InvalidArgument(m_path.string() + ": frame " + std::to_string(index) + " is outside the video's " +
                          std::to_string(m_info.frames) + " frames");
  Decoder& d = *m_decoder;
  if (d.next >= 0 && index > d.next && index - d.next <= kSkipAhead) {
    // A short step forward: decoding on (without converting) beats a seek back to the key frame.
    while (d.next < index && d.capture.grab())
      ++d.next;
  }
  if (index != d.next) {
    // FFmpeg's seek lands on the key frame at or before the target and decodes up to it.
    if (!d.capture.set(cv::CAP_PROP_POS_FRAMES, static_cast<double>(index)))
      throw FormatError(m_path.string(), "cannot seek to frame " + std::to_string(index));
    d.next = index;
  }
  if (!d.capture.read(d.bgr) || d.bgr.empty()) {
    d.next = -1;  // the decoder's position is unknown now: the next call seeks
    throw FormatError(m_path.string(), "cannot decode frame " + std::to_string(index));
  }
  ++d.next;
  VideoImage image;
  image.frame = index;
  image.width = d.bgr.cols;
  image.height = d.bgr.rows;
  image.rgb.resize(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3);
  cv::Mat rgb(image.height, image.width, CV_8UC3, image.rgb.data());
  cv::cvtColor(d.bgr, rgb, cv::COLOR_BGR2RGB);
  return image;
}

} // namespace mocap
