#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// Where a stream goes: a host name or address and a UDP port.
struct StreamDestination
{
  std::string host = "127.0.0.1";
  int port = 0;
};

/// "HOST:PORT", "HOST" (with `defaultPort`), or "[IPv6]:PORT". Throws InvalidArgument for an
/// empty host or a port outside 1…65535. O(#text).
[[nodiscard]] StreamDestination parseStreamDestination(std::string_view text, int defaultPort);

/// "HOST:PORT" (IPv6 hosts in brackets), for messages.
[[nodiscard]] std::string describeDestination(const StreamDestination& destination);

/// A connected UDP socket to one destination: each send is one datagram. Connecting lets the
/// kernel report a refusal (nothing listening: ICMP port unreachable) on a later send, which is
/// how a closed port is noticed at all over UDP. Plain POSIX sockets, no dependency.
class UdpSender
{
public:
  /// Resolves the host (IPv4 or IPv6) and connects. Throws IoError "cannot resolve host 'x'"
  /// or naming the system's reason, InvalidArgument for a port outside 1…65535. The resolve may
  /// block while a DNS server answers: call it off the UI thread. O(1) plus the lookup.
  explicit UdpSender(const StreamDestination& destination);
  ~UdpSender();
  UdpSender(const UdpSender&) = delete;
  UdpSender& operator=(const UdpSender&) = delete;

  /// Sends one datagram without blocking. Returns nothing when the kernel took it, else what went
  /// wrong ("nothing listens on 127.0.0.1:11111 (connection refused)", "the datagram is too
  /// large", …): UDP promises no delivery, so an error is reported, not thrown, and the next send
  /// may succeed (a receiver started later). O(#bytes).
  [[nodiscard]] std::optional<std::string> send(const std::vector<std::uint8_t>& datagram);

  [[nodiscard]] const StreamDestination& destination() const { return m_destination; }

private:
  StreamDestination m_destination;
  int m_socket = -1;
};

} // namespace mocap
