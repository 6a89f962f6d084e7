#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mocap::test {

/// A UDP socket bound to 127.0.0.1 on a free port, for the live-stream tests: it reads datagrams
/// with the moment each arrived.
class LoopbackReceiver
{
public:
  LoopbackReceiver();
  ~LoopbackReceiver();
  LoopbackReceiver(const LoopbackReceiver&) = delete;
  LoopbackReceiver& operator=(const LoopbackReceiver&) = delete;

  [[nodiscard]] int port() const { return m_port; }

  struct Datagram
  {
    std::vector<std::uint8_t> bytes;
    std::chrono::steady_clock::time_point arrived;
  };

  /// Datagrams as they come, until `count` arrived or none came for `quiet` (default 0.2 s).
  std::vector<Datagram> receive(std::size_t count, std::chrono::milliseconds quiet = std::chrono::milliseconds(200));

  /// Drops the datagrams already queued (what was sent before a change under test), without waiting.
  void drain();

private:
  int m_socket = -1;
  int m_port = 0;
};

} // namespace mocap::test
