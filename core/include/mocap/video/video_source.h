#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace mocap {

/// What a video file holds, as its container says (and, for a variable-frame-rate file, as its
/// frames' timestamps say).
struct VideoInfo
{
  Eigen::Index frames = 0;
  double rate = 0.0;  ///< frames per second (the container's nominal rate)
  int width = 0;
  int height = 0;
  std::string codec;  ///< the FourCC, e.g. "avc1", "MJPG"
  /// The frames' timestamps disagree with frame / rate (a phone or screen recording): then
  /// `frameTimes` holds each frame's time and the mapping to the take goes by them.
  bool variableRate = false;
  std::vector<double> frameTimes;  ///< seconds from the first frame, ascending; empty unless variableRate
  [[nodiscard]] double seconds() const;
};

/// One decoded frame: 8-bit RGB, rows top to bottom, `width` · 3 bytes each.
struct VideoImage
{
  Eigen::Index frame = -1;
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;

  /// The bytes of a `width` × `height` RGB image (0 for a negative side).
  [[nodiscard]] static std::size_t byteCount(int width, int height)
  {
    return width > 0 && height > 0 ? static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3 : 0;
  }
};

/// A reference video read frame by frame through OpenCV's videoio (FFmpeg: MP4/H.264, MOV, AVI,
/// MKV, whatever Debian's FFmpeg decodes). frame(i) is exact: the next frame is read on; any
/// other is reached by decoding on from where a decoder is, when no key frame lies between (the
/// key frames are indexed from the packets at the first jump, without decoding), else by seeking
/// to the key frame at or before it and decoding forward, so a jump costs up to one group of
/// pictures. Two decoders share the work: the one used least long ago seeks, so the other keeps
/// its place (playback and a scrub elsewhere do not throw each other back). Opening checks the timestamps of the first frames and of
/// the last against frame / rate; when they disagree (variable frame rate) it reads every frame's
/// timestamp once (O(frames) decoding) and seeks by timestamp. Not thread-safe: one source per
/// thread (the studio decodes on a worker).
class VideoSource
{
public:
  /// Whether opening checks the frame timestamps (Check) or leaves it to checkFrameTimes()
  /// (Later: opening then reads only the header and one frame, for a caller that checks on a worker).
  enum class FrameTimes { Check, Later };

  /// Throws IoError for a file that does not exist or cannot be opened as a video, and
  /// FormatError for one with no frames (none decodes) or no frame rate.
  explicit VideoSource(const std::filesystem::path& path, FrameTimes times = FrameTimes::Check);
  ~VideoSource();
  VideoSource(VideoSource&&) noexcept;
  VideoSource& operator=(VideoSource&&) noexcept;

  [[nodiscard]] const VideoInfo& info() const { return m_info; }
  [[nodiscard]] const std::filesystem::path& path() const { return m_path; }

  /// Frame `index` (0-based), decoded. Throws InvalidArgument for an index outside the video and
  /// FormatError when the file cannot be decoded there. O(1) for the next frame, O(GOP) for a jump.
  [[nodiscard]] VideoImage frame(Eigen::Index index);

  /// Checks the timestamps of the first frames and of the last ones against frame / rate (once;
  /// opening does it unless told Later); when they disagree, reads every frame's timestamp
  /// (O(frames) decoding) and info() then says variableRate (or corrects the frame count).
  /// Otherwise O(kTail + one group of pictures) decoding.
  void checkFrameTimes();

private:
  struct Decoder;
  void readFrameTimes();
  /// The decoder to reach frame `index` with, and whether it decodes on to it (else it seeks):
  /// one that has it next or can decode on to it for no more than a seek costs, else the one
  /// used least long ago.
  struct Stream;
  [[nodiscard]] std::pair<Stream*, bool> pickStream(Eigen::Index index);

  std::unique_ptr<Decoder> m_decoder;
  std::filesystem::path m_path;
  VideoInfo m_info;
};

} // namespace mocap
