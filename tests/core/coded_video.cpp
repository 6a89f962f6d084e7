#include "coded_video.h"

#include "mocap/base/file_io.h"

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mocap::test {

VideoImage codedImage(Eigen::Index frame, int width, int height)
{
  VideoImage image;
  image.frame = frame;
  image.width = width;
  image.height = height;
  image.rgb.assign(VideoImage::byteCount(width, height), 0);
  const int bar = width / kCodedBits;
  for (int b = 0; b < kCodedBits; ++b) {
    if (((frame >> (kCodedBits - 1 - b)) & 1) == 0)
      continue;
    for (int y = 0; y < height; ++y)
      std::fill_n(image.rgb.begin() + (static_cast<std::ptrdiff_t>(y) * width + b * bar) * 3, bar * 3, std::uint8_t{255});
  }
  return image;
}

bool writeCodedVideo(const std::filesystem::path& path, int fourcc, double rate, int frames, int width, int height)
{
  cv::VideoWriter writer(path.string(), cv::CAP_FFMPEG, fourcc, rate, cv::Size(width, height));
  if (!writer.isOpened())
    return false;
  for (int f = 0; f < frames; ++f) {
    VideoImage image = codedImage(f, width, height);  // black and white: RGB and BGR alike
    writer.write(cv::Mat(height, width, CV_8UC3, image.rgb.data()));
  }
  return true;
}

namespace {

using Bytes = std::vector<unsigned char>;

std::uint32_t be32(const Bytes& b, std::size_t at)
{
  return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) | (std::uint32_t{b[at + 2]} << 8) | b[at + 3];
}

void putBe32(Bytes& b, std::size_t at, std::uint32_t v)
{
  for (int i = 0; i < 4; ++i)
    b[at + static_cast<std::size_t>(i)] = static_cast<unsigned char>(v >> (24 - 8 * i));
}

/// The offset of the first box of `type` among the boxes in [begin, end), or nullopt.
std::optional<std::size_t> findBox(const Bytes& b, std::size_t begin, std::size_t end, const char* type)
{
  for (std::size_t at = begin; at + 8 <= end;) {
    const std::uint32_t size = be32(b, at);
    if (size < 8 || at + size > end)
      return std::nullopt;
    if (std::string(b.begin() + static_cast<std::ptrdiff_t>(at + 4), b.begin() + static_cast<std::ptrdiff_t>(at + 8)) == type)
      return at;
    at += size;
  }
  return std::nullopt;
}

/// The box at the end of `path` (moov, trak, …), with the offsets of the boxes on the way.
std::optional<std::vector<std::size_t>> boxPath(const Bytes& b, const std::vector<const char*>& path)
{
  std::vector<std::size_t> chain;
  std::size_t begin = 0, end = b.size();
  for (const char* type : path) {
    const auto at = findBox(b, begin, end, type);
    if (!at)
      return std::nullopt;
    chain.push_back(*at);
    begin = *at + 8;
    end = *at + be32(b, *at);
  }
  return chain;
}

/// Scales the version-0 duration field `at` bytes into box `box` by `factor`.
bool scaleDuration(Bytes& b, std::optional<std::vector<std::size_t>> chain, std::size_t at, double factor)
{
  if (!chain || b[chain->back() + 8] != 0)
    return false;
  const std::size_t field = chain->back() + at;
  putBe32(b, field, static_cast<std::uint32_t>(static_cast<double>(be32(b, field)) * factor + 0.5));
  return true;
}

} // namespace

bool writeVariableRateCodedVideo(const std::filesystem::path& path, double rate, int frames, int width, int height,
                                 int slowFrom)
{
  if (!writeCodedVideo(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), rate, frames, width, height))
    return false;
  const std::string written = readFileBytes(path);
  Bytes b(written.begin(), written.end());
  // The moov box follows the media data (FFmpeg writes it last), so growing it moves no sample.
  const auto stts = boxPath(b, {"moov", "trak", "mdia", "minf", "stbl", "stts"});
  if (!stts || be32(b, stts->back()) != 24 || be32(b, stts->back() + 12) != 1 ||
      be32(b, stts->back() + 16) != static_cast<std::uint32_t>(frames))
    return false;
  const std::size_t table = stts->back() + 12;
  const std::uint32_t delta = be32(b, table + 8);
  Bytes entries(20);
  putBe32(entries, 0, 2);
  putBe32(entries, 4, static_cast<std::uint32_t>(slowFrom));
  putBe32(entries, 8, delta);
  putBe32(entries, 12, static_cast<std::uint32_t>(frames - slowFrom));
  putBe32(entries, 16, 2 * delta);
  b.erase(b.begin() + static_cast<std::ptrdiff_t>(table), b.begin() + static_cast<std::ptrdiff_t>(table + 12));
  b.insert(b.begin() + static_cast<std::ptrdiff_t>(table), entries.begin(), entries.end());
  for (const std::size_t box : *stts)
    putBe32(b, box, be32(b, box) + 8);
  // The durations (movie, track, edit and media) grow with the slow frames.
  const double factor = static_cast<double>(2 * frames - slowFrom) / frames;
  if (!scaleDuration(b, boxPath(b, {"moov", "mvhd"}), 24, factor) ||
      !scaleDuration(b, boxPath(b, {"moov", "trak", "tkhd"}), 28, factor) ||
      !scaleDuration(b, boxPath(b, {"moov", "trak", "mdia", "mdhd"}), 24, factor))
    return false;
  if (const auto elst = boxPath(b, {"moov", "trak", "edts", "elst"}))
    if (!scaleDuration(b, elst, 16, factor))
      return false;
  writeFileAtomically(path, std::string_view(reinterpret_cast<const char*>(b.data()), b.size()));
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

Eigen::Index codedFrameNumber(const VideoImage& image)
{
  return codedFrameNumber(image.width, image.height, [&](int x, int y) {
    const auto at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) * 3;
    return image.rgb[at + 1] > 128;
  });
}

} // namespace mocap::test
