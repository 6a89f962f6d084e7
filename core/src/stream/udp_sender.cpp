#include "mocap/stream/udp_sender.h"

#include "mocap/base/error.h"

#include <cerrno>
#include <cstring>

#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

namespace mocap {

namespace {

constexpr int kMaxPort = 65535;

void checkPort(int port)
{
  if (port < 1 || port > kMaxPort)
    throw InvalidArgument("the port must be 1…65535, not " + std::to_string(port));
}

int parsePort(std::string_view text)
{
  if (text.empty() || text.size() > 5 || text.find_first_not_of("0123456789") != std::string_view::npos)
    throw InvalidArgument("'" + std::string(text) + "' is not a port number (1…65535)");
  const int port = std::stoi(std::string(text));
  checkPort(port);
  return port;
}

/// A socket connected to the first address of `destination` that takes one.
int connectedSocket(const StreamDestination& destination)
{
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_DGRAM;
  addrinfo* found = nullptr;
  const std::string port = std::to_string(destination.port);
  const int status = getaddrinfo(destination.host.c_str(), port.c_str(), &hints, &found);
  if (status != 0)
    throw IoError("cannot resolve host '" + destination.host + "': " + gai_strerror(status));
  std::string reason = "no address";
  int fd = -1;
  for (const addrinfo* address = found; address != nullptr && fd < 0; address = address->ai_next) {
    fd = socket(address->ai_family, address->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, address->ai_protocol);
    if (fd < 0) {
      reason = std::strerror(errno);
      continue;
    }
    if (connect(fd, address->ai_addr, address->ai_addrlen) != 0) {
      reason = std::strerror(errno);
      close(fd);
      fd = -1;
    }
  }
  freeaddrinfo(found);
  if (fd < 0)
    throw IoError("cannot send to " + describeDestination(destination) + ": " + reason);
  return fd;
}

} // namespace

StreamDestination parseStreamDestination(std::string_view text, int defaultPort)
{
  StreamDestination destination;
  destination.port = defaultPort;
  std::string_view host = text;
  if (!text.empty() && text.front() == '[') {
    const std::size_t close = text.find(']');
    if (close == std::string_view::npos)
      throw InvalidArgument("'" + std::string(text) + "': an IPv6 address in brackets needs its ']'");
    host = text.substr(1, close - 1);
    const std::string_view rest = text.substr(close + 1);
    if (!rest.empty()) {
      if (rest.front() != ':')
        throw InvalidArgument("'" + std::string(text) + "' is not HOST:PORT");
      destination.port = parsePort(rest.substr(1));
    }
  } else if (const std::size_t colon = text.rfind(':');
             colon != std::string_view::npos && text.find(':') == colon) {  // one colon: HOST:PORT
    host = text.substr(0, colon);
    destination.port = parsePort(text.substr(colon + 1));
  }
  if (host.empty())
    throw InvalidArgument("'" + std::string(text) + "' names no host (HOST:PORT, e.g. 127.0.0.1:" +
                          std::to_string(defaultPort) + ")");
  checkPort(destination.port);
  destination.host = std::string(host);
  return destination;
}

std::string describeDestination(const StreamDestination& destination)
{
  const bool ipv6 = destination.host.find(':') != std::string::npos;
  return (ipv6 ? "[" + destination.host + "]" : destination.host) + ":" + std::to_string(destination.port);
}

UdpSender::UdpSender(const StreamDestination& destination) : m_destination(destination)
{
  checkPort(destination.port);
  m_socket = connectedSocket(destination);
}

UdpSender::~UdpSender()
{
  if (m_socket >= 0)
    close(m_socket);
}

std::optional<std::string> UdpSender::send(const std::vector<std::uint8_t>& datagram)
{
  const ssize_t sent = ::send(m_socket, datagram.data(), datagram.size(), MSG_NOSIGNAL);
  if (sent == static_cast<ssize_t>(datagram.size()))
    return std::nullopt;
  if (sent >= 0)
    return "only " + std::to_string(sent) + " of " + std::to_string(datagram.size()) + " bytes went out";
  const int error = errno;
  if (error == ECONNREFUSED)
    return "nothing listens on " + describeDestination(m_destination) + " (connection refused)";
  if (error == EMSGSIZE)
    return "a datagram of " + std::to_string(datagram.size()) + " bytes is too large for the network";
  if (error == EAGAIN || error == EWOULDBLOCK)
    return "the network is busy: a datagram was dropped";
  return std::string("cannot send to ") + describeDestination(m_destination) + ": " + std::strerror(error);
}

} // namespace mocap
