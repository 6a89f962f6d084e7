#include "mocap/stream/live_streamer.h"

#include "mocap/base/enum_table.h"
#include "mocap/base/error.h"
#include "mocap/stream/live_link_face_packet.h"
#include "mocap/stream/vmc_packet.h"

#include <cmath>
#include <cstdio>
#include <random>

namespace mocap {

namespace {

constexpr EnumTable<StreamProtocol, 2> kProtocols{{{
    {StreamProtocol::LiveLink, "livelink"},
    {StreamProtocol::Vmc, "vmc"},
}}};

constexpr std::size_t kMaxLatenessSamples = 1'000'000;

using Clock = std::chrono::steady_clock;

/// The frame rate as Live Link's rational: whole rates over 1, NTSC's 23.976/29.97/59.94 over
/// 1001, anything else in thousandths.
std::pair<std::int32_t, std::int32_t> rationalRate(double rate)
{
  if (std::abs(rate - std::round(rate)) < 1e-6)
    return {static_cast<std::int32_t>(std::lround(rate)), 1};
  const double ntsc = rate * 1.001;
  if (std::abs(ntsc - std::round(ntsc)) < 1e-3)
    return {static_cast<std::int32_t>(std::lround(ntsc)) * 1000, 1001};
  return {static_cast<std::int32_t>(std::lround(rate * 1000.0)), 1000};
}

Clock::time_point dueTime(Clock::time_point start, std::int64_t tick, double rate)
{
  return start + std::chrono::duration_cast<Clock::duration>(
                     std::chrono::duration<double>(static_cast<double>(tick) / rate));
}

} // namespace

std::string_view streamProtocolName(StreamProtocol protocol)
{
  return kProtocols.name(protocol, "unknown");
}

std::optional<StreamProtocol> parseStreamProtocol(std::string_view name)
{
  return kProtocols.parse(name);
}

std::string streamProtocolNames()
{
  return kProtocols.names();
}

int defaultStreamPort(StreamProtocol protocol)
{
  return protocol == StreamProtocol::Vmc ? kVmcPort : kLiveLinkFacePort;
}

void checkStreamSettings(const StreamSettings& settings, const StreamFrames& frames)
{
  const double rate = settings.rate > 0.0 ? settings.rate : frames.frameRate;
  if (settings.rate < 0.0 || !(rate > 0.0) || rate > kMaxStreamRate || !std::isfinite(rate))
    throw InvalidArgument("a stream's rate must be above 0 and at most 1000 Hz, not " + std::to_string(rate));
  if (settings.protocol == StreamProtocol::LiveLink) {
    if (settings.sendMarkers)
      throw InvalidArgument("Live Link Face carries no markers: stream them over VMC");
    if (!frames.hasCurves())
      throw InvalidArgument("Live Link Face streams blendshape weights: solve the take to a rig first (or stream "
                            "markers over VMC)");
    if (settings.subject.size() > kLiveLinkFaceMaxNameBytes || settings.deviceId.size() > kLiveLinkFaceMaxNameBytes)
      throw InvalidArgument("Live Link Face's subject name and device id take at most 255 bytes");
  }
  const bool weights = settings.sendWeights && frames.hasCurves();
  const bool markers = settings.sendMarkers && frames.hasMarkers();
  if (!weights && !markers)
    throw InvalidArgument(settings.sendMarkers ? "the take has no markers to stream"
                                               : "there is nothing to stream: no solved weights, no markers asked for");
  if (frames.frameCount() == 0)
    throw InvalidArgument("there are no frames to stream");
}

std::string randomDeviceId()
{
  std::random_device device;
  std::uint8_t bytes[16];
  for (std::uint8_t& byte : bytes)
    byte = static_cast<std::uint8_t>(device());
  bytes[6] = static_cast<std::uint8_t>((bytes[6] & 0x0F) | 0x40);  // version 4
  bytes[8] = static_cast<std::uint8_t>((bytes[8] & 0x3F) | 0x80);  // RFC 4122 variant
  char text[37];
  std::snprintf(text, sizeof text, "%02X%02X%02X%02X-%02X%02X-%02X%02X-%02X%02X-%02X%02X%02X%02X%02X%02X", bytes[0],
                bytes[1], bytes[2], bytes[3], bytes[4], bytes[5], bytes[6], bytes[7], bytes[8], bytes[9], bytes[10],
                bytes[11], bytes[12], bytes[13], bytes[14], bytes[15]);
  return text;
}

StreamEncoder::StreamEncoder(StreamSettings settings) : m_settings(std::move(settings))
{
  m_liveLink.deviceId = m_settings.deviceId.empty() ? randomDeviceId() : m_settings.deviceId;
  m_liveLink.subject = m_settings.subject;
  const auto& names = liveLinkFacePacketNames();
  for (std::size_t i = 0; i < 52; ++i)
    m_weightNames.emplace_back(names[i]);
}

const std::vector<std::uint8_t>& StreamEncoder::encode(const StreamFrames& frames, Eigen::Index row)
{
  if (m_settings.protocol == StreamProtocol::LiveLink) {
    m_liveLink.frame = static_cast<std::int32_t>(frames.firstFrame + row);
    std::tie(m_liveLink.rateNumerator, m_liveLink.rateDenominator) = rationalRate(frames.frameRate);
    for (std::size_t i = 0; i < LiveLinkFaceFrame::kValues; ++i)
      m_liveLink.values[i] = frames.curves(row, static_cast<Eigen::Index>(i));
    encodeLiveLinkFacePacket(m_liveLink, m_buffer);
    return m_buffer;
  }
  const bool weights = m_settings.sendWeights && frames.hasCurves();
  const bool markers = m_settings.sendMarkers && frames.hasMarkers();
  using RowRef = Eigen::Ref<const Eigen::RowVectorXf>;
  static const Eigen::RowVectorXf none;
  // Rows of row-major matrices: the references point into the frames, nothing is copied.
  const RowRef values = weights ? RowRef(frames.curves.row(row).head(52)) : RowRef(none);
  const RowRef positions = markers ? RowRef(frames.markers.row(row)) : RowRef(none);
  encodeVmcFrame(weights ? m_weightNames : m_noNames, values, markers ? frames.markerNames : m_noNames, positions,
                 m_buffer);
  return m_buffer;
}

LiveStreamer::LiveStreamer(StreamSettings settings, std::shared_ptr<const StreamFrames> frames)
    : m_settings(std::move(settings)), m_sender((checkStreamSettings(m_settings, *frames), m_settings.destination)),
      m_frames(std::move(frames))
{
  if (m_settings.deviceId.empty())
    m_settings.deviceId = randomDeviceId();
  m_rate = m_settings.rate > 0.0 ? m_settings.rate : m_frames->frameRate;
}

LiveStreamer::~LiveStreamer()
{
  stop();
}

void LiveStreamer::playRange(Eigen::Index first, Eigen::Index last, bool loop)
{
  Eigen::Index count = 0;
  double frameRate = 0.0;
  {
    const std::lock_guard<std::mutex> lock(m_mutex);
    count = m_frames->frameCount();
    frameRate = m_frames->frameRate;
  }
  if (first < 0 || last < first || last >= count)
    throw InvalidArgument("frames " + std::to_string(first) + "…" + std::to_string(last) + " are not within the " +
                          std::to_string(count) + " frames to stream");
  start({first, last, frameRate, loop, false});
}

void LiveStreamer::followCurrentFrame()
{
  start({0, 0, 0.0, false, true});
}

void LiveStreamer::setFrames(std::shared_ptr<const StreamFrames> frames)
{
  checkStreamSettings(m_settings, *frames);
  const std::lock_guard<std::mutex> lock(m_mutex);
  m_frames = std::move(frames);
}

void LiveStreamer::start(Range range)
{
  if (m_thread.joinable()) {
    if (m_running.load())
      throw InvalidArgument("the stream is already running");
    m_thread.join();
  }
  m_stop.store(false);
  {
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_stats = StreamStats{};
    m_start = Clock::now();
  }
  m_running.store(true);
  m_thread = std::thread([this, range] { run(range); });
}

void LiveStreamer::stop()
{
  {
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_stop.store(true);
  }
  m_wake.notify_all();
  if (m_thread.joinable())
    m_thread.join();
}

void LiveStreamer::wait()
{
  if (m_thread.joinable())
    m_thread.join();
}

StreamStats LiveStreamer::stats() const
{
  const std::lock_guard<std::mutex> lock(m_mutex);
  return m_stats;
}

std::chrono::steady_clock::time_point LiveStreamer::startTime() const
{
  const std::lock_guard<std::mutex> lock(m_mutex);
  return m_start;
}

Eigen::Index LiveStreamer::rowOfTick(const Range& range, std::int64_t tick) const
{
  if (range.follow)
    return m_current.load(std::memory_order_relaxed);
  const auto offset =
      static_cast<std::int64_t>(std::floor(static_cast<double>(tick) * range.frameRate / m_rate + 0.5));
  const std::int64_t count = range.last - range.first + 1;
  if (!range.loop)
    return offset < count ? range.first + offset : -1;
  return range.first + offset % count;
}

bool LiveStreamer::sendRow(StreamEncoder& encoder, Eigen::Index row, Clock::time_point due)
{
  std::shared_ptr<const StreamFrames> frames;
  {
    const std::lock_guard<std::mutex> lock(m_mutex);
    frames = m_frames;
  }
  row = std::clamp<Eigen::Index>(row, 0, frames->frameCount() - 1);
  const std::optional<std::string> error = m_sender.send(encoder.encode(*frames, row));
  const float late = std::chrono::duration<float>(Clock::now() - due).count();
  const std::lock_guard<std::mutex> lock(m_mutex);
  if (error) {
    ++m_stats.failed;
    m_stats.lastError = *error;
  } else {
    ++m_stats.sent;
  }
  m_stats.lastRow = row;
  if (m_stats.lateness.size() < kMaxLatenessSamples)
    m_stats.lateness.push_back(late);
  return !error;
}

void LiveStreamer::run(Range range)
{
  StreamEncoder encoder(m_settings);
  const Clock::time_point start = startTime();
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / m_rate));
  for (std::int64_t tick = 0;; ++tick) {
    const Eigen::Index row = rowOfTick(range, tick);
    if (row < 0)
      break;
    Clock::time_point due = dueTime(start, tick, m_rate);
    if (range.follow && Clock::now() > due + period) {  // fell behind (a busy machine): skip ahead
      tick = static_cast<std::int64_t>(std::ceil(std::chrono::duration<double>(Clock::now() - start).count() * m_rate));
      due = dueTime(start, tick, m_rate);
    }
    {
      std::unique_lock<std::mutex> lock(m_mutex);
      if (m_wake.wait_until(lock, due, [this] { return m_stop.load(); }))
        break;
    }
    sendRow(encoder, row, due);
  }
  m_running.store(false);
}

} // namespace mocap
