#pragma once

#include <filesystem>
#include <memory>
#include <string>

namespace mocap {

struct VideoImage;

/// How a review video is encoded: the file actually written and the codec used.
struct ReviewEncoding
{
  std::filesystem::path path;  ///< where the video goes (".avi" when MP4 could not be written)
  std::string codec;           ///< FourCC: "avc1" (H.264), "mp4v" (MPEG-4 Part 2) or "MJPG"
  std::string container;       ///< "mp4" or "avi"
};

/// Writes a review video frame by frame through OpenCV's videoio (FFmpeg), atomically: the frames
/// go to a temporary file beside the target, and finish() flushes it and renames it into place. A
/// writer destroyed without finish() (cancelled, failed, an exception) removes the temporary file,
/// so no partial video is ever left.
///
/// For a ".mp4" target the encoders are tried in order H.264 ("avc1"), then MPEG-4 Part 2
/// ("mp4v"); when neither opens, the video is written as Motion JPEG in an AVI beside it (the
/// target's extension replaced by ".avi"), and encoding() says so. Any other extension is written
/// as Motion JPEG AVI. Not thread-safe; one frame costs one encode, O(width · height).
class ReviewVideoWriter
{
public:
  /// Throws InvalidArgument for a size that is not positive and even (encoders need even sizes)
  /// or a rate that is not positive and finite, and IoError when no encoder can write the file.
  ReviewVideoWriter(const std::filesystem::path& path, int width, int height, double rate);
  ~ReviewVideoWriter();
  ReviewVideoWriter(const ReviewVideoWriter&) = delete;
  ReviewVideoWriter& operator=(const ReviewVideoWriter&) = delete;

  [[nodiscard]] const ReviewEncoding& encoding() const { return m_encoding; }
  [[nodiscard]] int width() const { return m_width; }
  [[nodiscard]] int height() const { return m_height; }
  [[nodiscard]] long long framesWritten() const { return m_frames; }

  /// Appends one frame; throws InvalidArgument for an image of another size.
  void write(const VideoImage& image);
  /// Closes the video and puts it in place. Throws IoError when nothing was written or the file
  /// cannot be flushed or renamed (the temporary file is then removed).
  void finish();

private:
  struct Encoder;
  std::unique_ptr<Encoder> m_encoder;
  ReviewEncoding m_encoding;
  std::filesystem::path m_temporary;
  int m_width = 0;
  int m_height = 0;
  long long m_frames = 0;
};

} // namespace mocap
