#include "mocap/video/review_video_writer.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/video/video_source.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <cmath>

namespace mocap {

struct ReviewVideoWriter::Encoder
{
  cv::VideoWriter writer;
  cv::Mat bgr;
};

namespace {

struct Candidate
{
  const char* codec;
  const char* container;
};

int fourcc(const char* code)
{
  return cv::VideoWriter::fourcc(code[0], code[1], code[2], code[3]);
}

void removeQuietly(const std::filesystem::path& path)
{
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

} // namespace

ReviewVideoWriter::ReviewVideoWriter(const std::filesystem::path& path, int width, int height, double rate)
    : m_encoder(std::make_unique<Encoder>()), m_width(width), m_height(height)
{
  if (width <= 0 || height <= 0 || width % 2 != 0 || height % 2 != 0)
    throw InvalidArgument("review video: the size must be positive and even, not " + std::to_string(width) + " x " +
                          std::to_string(height));
  if (!(rate > 0.0) || !std::isfinite(rate))
    throw InvalidArgument("review video: the frame rate must be positive");
  const bool mp4 = lowerExtension(path) == "mp4";
  const std::vector<Candidate> candidates =
      mp4 ? std::vector<Candidate>{{"avc1", "mp4"}, {"mp4v", "mp4"}, {"MJPG", "avi"}} : std::vector<Candidate>{{"MJPG", "avi"}};
  for (const Candidate& candidate : candidates) {
    std::filesystem::path target = path;
    if (std::string(candidate.container) == "avi")
      target.replace_extension(".avi");
    const std::filesystem::path temporary = temporaryPathBeside(target);
    // FFmpeg prints why an encoder is missing; the fallback is ours to report, through encoding().
    if (m_encoder->writer.open(temporary.string(), cv::CAP_FFMPEG, fourcc(candidate.codec), rate, cv::Size(width, height)) &&
        m_encoder->writer.isOpened()) {
      m_encoding = {target, candidate.codec, candidate.container};
      m_temporary = temporary;
      return;
    }
    removeQuietly(temporary);
  }
  throw IoError(path.string() + ": no video encoder can write this file (is the folder writable?)");
}

ReviewVideoWriter::~ReviewVideoWriter()
{
  if (m_encoder && m_encoder->writer.isOpened()) {
    m_encoder->writer.release();
    removeQuietly(m_temporary);
  }
}

void ReviewVideoWriter::write(const VideoImage& image)
{
  if (!m_encoder->writer.isOpened())
    throw IoError(m_encoding.path.string() + ": write after finish");
  if (image.width != m_width || image.height != m_height ||
      image.rgb.size() != VideoImage::byteCount(m_width, m_height))
    throw InvalidArgument("review video: a " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                          " frame for a " + std::to_string(m_width) + " x " + std::to_string(m_height) + " video");
  const cv::Mat rgb(m_height, m_width, CV_8UC3, const_cast<std::uint8_t*>(image.rgb.data()));
  cv::cvtColor(rgb, m_encoder->bgr, cv::COLOR_RGB2BGR);
  m_encoder->writer.write(m_encoder->bgr);
  ++m_frames;
}

void ReviewVideoWriter::finish()
{
  if (!m_encoder->writer.isOpened())
    throw IoError(m_encoding.path.string() + ": finished twice");
  m_encoder->writer.release();
  if (m_frames == 0) {
    removeQuietly(m_temporary);
    throw IoError(m_encoding.path.string() + ": no frames to write");
  }
  std::error_code error;
  if (std::filesystem::file_size(m_temporary, error) == 0 || error) {
    removeQuietly(m_temporary);
    throw IoError(m_encoding.path.string() + ": the encoder wrote nothing (is the disk full?)");
  }
  publishFile(m_temporary, m_encoding.path);
}

} // namespace mocap
