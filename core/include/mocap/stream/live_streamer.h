#pragma once

#include "mocap/stream/live_link_face_packet.h"
#include "mocap/stream/stream_frames.h"
#include "mocap/stream/udp_sender.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace mocap {

/// The wire formats a live stream speaks.
enum class StreamProtocol
{
  LiveLink,  ///< Live Link Face (Epic's iPhone app): Unreal, MetaHuman, Blender and Godot receivers
  Vmc,       ///< the VMC protocol (OSC): VSeeFace, VMagicMirror, Inochi Session, Blender add-ons
};

[[nodiscard]] std::string_view streamProtocolName(StreamProtocol protocol);  ///< "livelink", "vmc"
[[nodiscard]] std::optional<StreamProtocol> parseStreamProtocol(std::string_view name);
[[nodiscard]] std::string streamProtocolNames();  ///< "livelink|vmc"
[[nodiscard]] int defaultStreamPort(StreamProtocol protocol);  ///< 11111, 39539

/// The highest send rate accepted: a frame every millisecond is already past what a receiver shows.
inline constexpr double kMaxStreamRate = 1000.0;

struct StreamSettings
{
  StreamProtocol protocol = StreamProtocol::LiveLink;
  StreamDestination destination{"127.0.0.1", 11111};
  std::string subject = "MocapStudio";  ///< Live Link's subject name
  std::string deviceId;                 ///< Live Link's device id; empty: a random UUID per streamer
  bool sendWeights = true;
  bool sendMarkers = false;             ///< VMC only: each marker as a tracker (/VMC/Ext/Tra/Pos)
  double rate = 0.0;                    ///< datagrams per second; 0: the frames' own rate
};

/// Throws InvalidArgument naming what cannot be streamed: a rate outside (0, 1000] Hz, frames
/// without the weights Live Link sends (a take without a solved rig), markers asked of Live Link,
/// nothing to send, a subject over 255 bytes. O(1).
void checkStreamSettings(const StreamSettings& settings, const StreamFrames& frames);

/// A random version-4 UUID in the 36-character text form Live Link Face's device ids take. O(1).
[[nodiscard]] std::string randomDeviceId();

/// Encodes a frame as its protocol's datagram into a buffer it reuses (no allocation once grown).
class StreamEncoder
{
public:
  explicit StreamEncoder(StreamSettings settings);
  /// The datagram of `row`. O(61) for Live Link, O(#weights + #markers) for VMC.
  const std::vector<std::uint8_t>& encode(const StreamFrames& frames, Eigen::Index row);

private:
  StreamSettings m_settings;
  LiveLinkFaceFrame m_liveLink;  // device id and subject set once
  std::vector<std::uint8_t> m_buffer;
  std::vector<std::string> m_weightNames;  // VMC: the 52 ARKit names in the packet's order
  std::vector<std::string> m_noNames;
};

/// What a streamer has done so far.
struct StreamStats
{
  std::int64_t sent = 0;     ///< datagrams the network took
  std::int64_t failed = 0;   ///< datagrams refused (nothing listening, too large, …)
  std::string lastError;     ///< the latest refusal's reason, empty when none
  Eigen::Index lastRow = -1; ///< the last frame sent (row of the frames)
  /// Per datagram, seconds from its due time to the moment the send returned (the first 10^6).
  std::vector<float> lateness;
};

/// Sends frames over UDP from a thread of its own on a monotonic schedule: datagram i is due at
/// start + i / rate (steady clock), so timing does not drift however long the stream runs, and
/// nothing ever waits on the caller's thread. Datagram i carries the frame at time i / rate of
/// the part played (nearest frame), so a take streamed at another rate still plays at its speed.
class LiveStreamer
{
public:
  /// Checks the settings (checkStreamSettings) and connects (UdpSender): throws as they do. The
  /// host lookup may block: construct off the UI thread when the host is a name.
  LiveStreamer(StreamSettings settings, std::shared_ptr<const StreamFrames> frames);
  ~LiveStreamer();  ///< stops and joins
  LiveStreamer(const LiveStreamer&) = delete;
  LiveStreamer& operator=(const LiveStreamer&) = delete;

  /// Plays rows first…last in real time, once or looping, then stops by itself (not looping).
  /// Throws InvalidArgument for rows outside the frames or a streamer already running.
  void playRange(Eigen::Index first, Eigen::Index last, bool loop);
  /// Sends the current frame (setCurrentFrame) at every tick until stop(): the studio moves it as
  /// it plays, scrubs or edits. A tick missed by more than one period is skipped, not caught up.
  void followCurrentFrame();
  void setCurrentFrame(Eigen::Index row) { m_current.store(row, std::memory_order_relaxed); }
  /// New frames for the next tick (the take was edited, the solve rerun). Throws InvalidArgument
  /// as checkStreamSettings for frames the protocol cannot send.
  void setFrames(std::shared_ptr<const StreamFrames> frames);

  void stop();               ///< ends the stream at once (waits for the thread)
  void wait();               ///< until a range played once has finished (or stop)
  [[nodiscard]] bool running() const { return m_running.load(); }
  [[nodiscard]] StreamStats stats() const;
  [[nodiscard]] double rate() const { return m_rate; }
  /// When datagram 0 was due: datagram i is due at startTime() + i / rate().
  [[nodiscard]] std::chrono::steady_clock::time_point startTime() const;
  [[nodiscard]] const StreamSettings& settings() const { return m_settings; }

private:
  struct Range
  {
    Eigen::Index first = 0, last = 0;
    double frameRate = 0.0;  // of the frames when the range started
    bool loop = false, follow = false;
  };
  void start(Range range);
  void run(Range range);
  /// The row datagram `tick` carries, or -1 once a range played once has ended.
  Eigen::Index rowOfTick(const Range& range, std::int64_t tick) const;
  bool sendRow(StreamEncoder& encoder, Eigen::Index row, std::chrono::steady_clock::time_point due);

  StreamSettings m_settings;
  double m_rate = 0.0;
  UdpSender m_sender;
  mutable std::mutex m_mutex;  // guards m_frames, m_stats, m_start
  std::condition_variable m_wake;
  std::shared_ptr<const StreamFrames> m_frames;
  StreamStats m_stats;
  std::chrono::steady_clock::time_point m_start;
  std::atomic<Eigen::Index> m_current{0};
  std::atomic<bool> m_stop{false};
  std::atomic<bool> m_running{false};
  std::thread m_thread;
};

} // namespace mocap
