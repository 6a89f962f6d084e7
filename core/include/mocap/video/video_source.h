#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace mocap {

/// What a video file holds, as its container says.
struct VideoInfo
{
  Eigen::Index frames = 0;
  double rate = 0.0;  ///< frames per second
  int width = 0;
  int height = 0;
  std::string codec;  ///< the FourCC, e.g. "avc1", "MJPG"
  [[nodiscard]] double seconds() const { return rate > 0.0 ? static_cast<double>(frames) / rate : 0.0; }
};

/// One decoded frame: 8-bit RGB, rows top to bottom, `width` · 3 bytes each.
struct VideoImage
{
  Eigen::Index frame = -1;
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;
};

/// A reference video read frame by frame through OpenCV's videoio (FFmpeg: MP4/H.264, MOV, AVI,
/// MKV, whatever Debian's FFmpeg decodes). frame(i) is exact: the next frame is read on; any
/// other is reached by seeking to a key frame at or before it and decoding forward, so a jump
/// costs up to one group of pictures. Not thread-safe: one source per thread (the studio decodes
/// on a worker).
class VideoSource
{
public:
  /// Throws IoError for a file that does not exist or cannot be opened as a video, and
  /// FormatError for one with no frames or no frame rate.
  explicit VideoSource(const std::filesystem::path& path);
  ~VideoSource();
  VideoSource(VideoSource&&) noexcept;
  VideoSource& operator=(VideoSource&&) noexcept;

  [[nodiscard]] const VideoInfo& info() const { return m_info; }
  [[nodiscard]] const std::filesystem::path& path() const { return m_path; }

  /// Frame `index` (0-based), decoded. Throws InvalidArgument for an index outside the video and
  /// FormatError when the file cannot be decoded there. O(1) for the next frame, O(GOP) for a jump.
  [[nodiscard]] VideoImage frame(Eigen::Index index);

private:
  struct Decoder;
  std::unique_ptr<Decoder> m_decoder;
  std::filesystem::path m_path;
  VideoInfo m_info;
};

} // namespace mocap
