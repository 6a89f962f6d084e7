#include "mocap/video/video_source.h"

#include "mocap/base/error.h"
#include "mocap/video/video_sync.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace mocap {

struct VideoSource::Stream
{
  cv::VideoCapture capture;
  Eigen::Index next = 0;   // the frame the next read() returns; −1: unknown
  std::uint64_t used = 0;  // when it last decoded (a count): the one used least long ago seeks
};

struct VideoSource::Decoder
{
  // Two decoders of the file: one can stay where playback is while the other seeks (the second
  // is opened at the first jump).
  Stream streams[2];
  std::uint64_t uses = 0;
  double firstTime = 0.0;  // the first frame's timestamp (s): frame times count from it
  std::vector<Eigen::Index> keyFrames;  // ascending; empty: unknown
  bool keyFramesRead = false;
  bool timesChecked = false;
  cv::Mat bgr;
};

namespace {

/// Forward jumps up to this many frames decode on instead of seeking (a seek decodes from the key
/// frame before the target, which may be hundreds of frames back).
constexpr Eigen::Index kSkipAhead = 48;

/// Frames whose timestamps opening checks against frame / rate (besides the last).
constexpr Eigen::Index kProbeFrames = 24;
/// The frames at the end whose timestamps and count opening checks.
constexpr Eigen::Index kTailFrames = 16;
/// The most frames at the end a decoder may hand out without a timestamp (drained B-frame delay).
constexpr std::size_t kDrainedFrames = 4;

/// The timestamp (s) of the frame grab() read last.
double grabbedTime(const cv::VideoCapture& capture)
{
  return capture.get(cv::CAP_PROP_POS_MSEC) / 1000.0;
}

/// Whether `time` is frame `index`'s time at `rate`, within half a frame.
bool onRate(double time, Eigen::Index index, double rate)
{
  return std::abs(time - static_cast<double>(index) / rate) <= 0.5 / rate;
}

/// Frames OpenCV's seek may decode beyond the key frame: it aims this many frames early.
constexpr Eigen::Index kSeekLead = 16;

/// The key frames' indices (ascending) from the packets' key flags, read without decoding
/// (OpenCV's raw mode): O(frames) demuxing. Empty when the packets do not match the frames.
std::vector<Eigen::Index> readKeyFrames(const std::filesystem::path& path, Eigen::Index frames)
{
  cv::VideoCapture raw;
  if (!raw.open(path.string(), cv::CAP_FFMPEG, {cv::CAP_PROP_FORMAT, -1}))
    return {};
  std::vector<Eigen::Index> keys;
  Eigen::Index packets = 0;
  for (; packets <= frames && raw.grab(); ++packets)
    if (raw.get(cv::CAP_PROP_LRF_HAS_KEY_FRAME) != 0.0)
      keys.push_back(packets);
  if (packets != frames || keys.empty() || keys.front() != 0)
    return {};
  return keys;
}

/// The last key frame at or before `index`.
Eigen::Index keyFrameAtOrBefore(const std::vector<Eigen::Index>& keys, Eigen::Index index)
{
  const auto after = std::upper_bound(keys.begin(), keys.end(), index);
  return after == keys.begin() ? 0 : *std::prev(after);
}

/// Positions `capture` so that frame `index` of a variable-frame-rate video (frame times
/// `times`, counted from `firstTime`) is grabbed: OpenCV seeks to a frame number it takes for
/// time · nominal `rate`, so land a little before the target's time, then decode on, telling
/// frames apart by their timestamps. False when it cannot get there.
bool seekByTime(cv::VideoCapture& capture, const std::vector<double>& times, double firstTime, double rate,
                Eigen::Index index)
{
  for (double back = 0.5; back < 4.0 * times.back() + 8.0; back *= 4.0) {
    const double at = std::max(0.0, times[static_cast<std::size_t>(index)] - back);
    if (!capture.set(cv::CAP_PROP_POS_FRAMES, std::floor(at * rate)) || !capture.grab())
      return false;
    Eigen::Index landed = nearestFrame(times, grabbedTime(capture) - firstTime);
    if (landed > index && at > 0.0)
      continue;  // landed past it: go back farther
    while (landed < index && capture.grab())
      landed = nearestFrame(times, grabbedTime(capture) - firstTime);
    return landed == index;
  }
  return false;
}

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

VideoSource::VideoSource(const std::filesystem::path& path, FrameTimes times)
    : m_decoder(std::make_unique<Decoder>()), m_path(path)
{
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw IoError(path.string() + ": no such video file");
  cv::VideoCapture& capture = m_decoder->streams[0].capture;
  if (!capture.open(path.string(), cv::CAP_FFMPEG) || !capture.isOpened())
    throw IoError(path.string() + ": not a video this build can decode");
  m_info.frames = static_cast<Eigen::Index>(std::llround(capture.get(cv::CAP_PROP_FRAME_COUNT)));
  m_info.rate = capture.get(cv::CAP_PROP_FPS);
  m_info.width = static_cast<int>(capture.get(cv::CAP_PROP_FRAME_WIDTH));
  m_info.height = static_cast<int>(capture.get(cv::CAP_PROP_FRAME_HEIGHT));
  m_info.codec = fourcc(capture.get(cv::CAP_PROP_FOURCC));
  if (!(m_info.rate > 0.0) || !std::isfinite(m_info.rate))
    throw FormatError(path.string(), "the video has no frame rate");
  if (m_info.frames <= 0 || m_info.width <= 0 || m_info.height <= 0)
    throw FormatError(path.string(), "the video has no frames");
  if (!capture.grab())
    throw FormatError(path.string(), "the video has no frames (none decodes)");
  capture.set(cv::CAP_PROP_POS_FRAMES, 0.0);
  if (times == FrameTimes::Check)
    checkFrameTimes();
}

double VideoInfo::seconds() const
{
  if (variableRate && frameTimes.size() >= 2)  // the last frame lasts as long as the one before it
    return 2.0 * frameTimes.back() - frameTimes[frameTimes.size() - 2];
  return rate > 0.0 ? static_cast<double>(frames) / rate : 0.0;
}

void VideoSource::checkFrameTimes()
{
  Decoder& d = *m_decoder;
  if (d.timesChecked)
    return;
  d.timesChecked = true;
  cv::VideoCapture& capture = d.streams[0].capture;
  capture.set(cv::CAP_PROP_POS_FRAMES, 0.0);
  const Eigen::Index probe = std::min(m_info.frames, kProbeFrames);
  bool regular = true;
  Eigen::Index read = 0;
  for (; read < probe && capture.grab(); ++read) {
    const double time = grabbedTime(capture);
    if (read == 0)
      d.firstTime = time;
    regular = regular && onRate(time - d.firstTime, read, m_info.rate);
  }
  regular = regular && read == probe;
  if (regular && m_info.frames > probe + kTailFrames) {
    // The last frames must sit where frame / rate puts them, with none after them. (OpenCV seeks
    // to time frame / rate, so a file slower at the end has more frames after that time, one
    // faster fewer.) The decoder's last frames, drained at the end, may come without a timestamp.
    const Eigen::Index from = m_info.frames - kTailFrames;
    Eigen::Index after = 0;
    double previous = -1.0;
    if (capture.set(cv::CAP_PROP_POS_FRAMES, static_cast<double>(from)))
      for (; after <= kTailFrames && capture.grab(); ++after) {
        const double time = grabbedTime(capture) - d.firstTime;
        if (time > previous)
          regular = regular && onRate(time, from + after, m_info.rate);
        previous = std::max(previous, time);
      }
    regular = regular && after == kTailFrames;
  }
  if (!regular)
    readFrameTimes();
  capture.set(cv::CAP_PROP_POS_FRAMES, 0.0);
  d.streams[0].next = 0;
}

void VideoSource::readFrameTimes()
{
  Decoder& d = *m_decoder;
  cv::VideoCapture& capture = d.streams[0].capture;
  capture.set(cv::CAP_PROP_POS_FRAMES, 0.0);
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(m_info.frames));
  while (capture.grab())
    times.push_back(grabbedTime(capture));
  if (times.empty())
    throw FormatError(m_path.string(), "the video has no frames (none decodes)");
  d.firstTime = times.front();
  bool regular = true, ascending = true;
  for (std::size_t i = 0; i < times.size(); ++i) {
    times[i] -= d.firstTime;
    if (i > 0 && times[i] <= times[i - 1] && times.size() - i <= kDrainedFrames)
      times[i] = times[i - 1] + (i > 1 ? times[i - 1] - times[i - 2] : 1.0 / m_info.rate);  // drained: no timestamp
    regular = regular && onRate(times[i], static_cast<Eigen::Index>(i), m_info.rate);
    ascending = ascending && (i == 0 || times[i] > times[i - 1]);
  }
  m_info.frames = static_cast<Eigen::Index>(times.size());  // the count the container gave was off
  // Timestamps that do not ascend cannot map time to frames: frame / rate is all there is.
  m_info.variableRate = !regular && ascending;
  if (m_info.variableRate)
    m_info.frameTimes = std::move(times);
}

VideoSource::~VideoSource() = default;
VideoSource::VideoSource(VideoSource&&) noexcept = default;
VideoSource& VideoSource::operator=(VideoSource&&) noexcept = default;

std::pair<VideoSource::Stream*, bool> VideoSource::pickStream(Eigen::Index index)
{
  Decoder& d = *m_decoder;
  for (Stream& stream : d.streams)
    if (stream.next == index && stream.capture.isOpened())
      return {&stream, true};  // the next frame of one of them
  if (!d.keyFramesRead) {
    d.keyFramesRead = true;
    d.keyFrames = readKeyFrames(m_path, m_info.frames);
  }
  // What a seek decodes: from the key frame before where OpenCV aims; unknown key frames: as
  // far as the short skips decoding on is allowed.
  const Eigen::Index seekCost =
      d.keyFrames.empty() ? kSkipAhead
                          : index - keyFrameAtOrBefore(d.keyFrames, std::max<Eigen::Index>(index - kSeekLead, 0));
  Stream* best = nullptr;
  for (Stream& stream : d.streams)
    if (stream.capture.isOpened() && stream.next >= 0 && stream.next < index && index - stream.next <= seekCost &&
        (!best || stream.next > best->next))
      best = &stream;
  if (best)
    return {best, true};  // decoding on from there costs no more than seeking
  Stream& second = d.streams[1];
  if (!second.capture.isOpened()) {
    if (!second.capture.open(m_path.string(), cv::CAP_FFMPEG) || !second.capture.isOpened())
      return {&d.streams[0], false};
    second.next = -1;  // wherever it is: it seeks
  }
  // Both would seek: the one used least long ago does, the other keeps its place.
  return {d.streams[0].used <= second.used ? &d.streams[0] : &second, false};
}

VideoImage VideoSource::frame(Eigen::Index index)
{
  if (index < 0 || index >= m_info.frames)
    throw InvalidArgument(m_path.string() + ": frame " + std::to_string(index) + " is outside the video's " +
                          std::to_string(m_info.frames) + " frames");
  Decoder& d = *m_decoder;
  const auto [stream, decodeOn] = pickStream(index);
  bool grabbed = false;  // frame `index` is grabbed, waiting to be decoded into an image
  if (decodeOn) {
    // Decoding on (without converting) beats a seek back to the key frame.
    while (stream->next < index && stream->capture.grab())
      ++stream->next;
  }
  if (index != stream->next) {
    if (m_info.variableRate) {
      if (!seekByTime(stream->capture, m_info.frameTimes, d.firstTime, m_info.rate, index)) {
        stream->next = -1;
        throw FormatError(m_path.string(), "cannot seek to frame " + std::to_string(index));
      }
      grabbed = true;
    } else if (!stream->capture.set(cv::CAP_PROP_POS_FRAMES, static_cast<double>(index))) {
      // FFmpeg's seek lands on the key frame at or before the target and decodes up to it.
      stream->next = -1;
      throw FormatError(m_path.string(), "cannot seek to frame " + std::to_string(index));
    }
    stream->next = index;
  }
  if (!(grabbed ? stream->capture.retrieve(d.bgr) : stream->capture.read(d.bgr)) || d.bgr.empty()) {
    stream->next = -1;  // the decoder's position is unknown now: the next call seeks
    throw FormatError(m_path.string(), "cannot decode frame " + std::to_string(index));
  }
  ++stream->next;
  stream->used = ++d.uses;
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
