#include "loopback_receiver.h"

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace mocap::test {

LoopbackReceiver::LoopbackReceiver()
{
  m_socket = socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  (void)bind(m_socket, reinterpret_cast<sockaddr*>(&address), sizeof address);
  socklen_t size = sizeof address;
  (void)getsockname(m_socket, reinterpret_cast<sockaddr*>(&address), &size);
  m_port = ntohs(address.sin_port);
  int buffer = 4 << 20;  // a whole test's datagrams fit while the test is busy elsewhere
  (void)setsockopt(m_socket, SOL_SOCKET, SO_RCVBUF, &buffer, sizeof buffer);
}

LoopbackReceiver::~LoopbackReceiver()
{
  close(m_socket);
}

std::vector<LoopbackReceiver::Datagram> LoopbackReceiver::receive(std::size_t count, std::chrono::milliseconds quiet)
{
  timeval timeout{static_cast<time_t>(quiet.count() / 1000), static_cast<suseconds_t>((quiet.count() % 1000) * 1000)};
  (void)setsockopt(m_socket, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  std::vector<Datagram> datagrams;
  std::vector<std::uint8_t> buffer(65536);
  while (datagrams.size() < count) {
    const ssize_t size = recv(m_socket, buffer.data(), buffer.size(), 0);
    if (size < 0)
      break;
    datagrams.push_back({std::vector<std::uint8_t>(buffer.begin(), buffer.begin() + size),
                         std::chrono::steady_clock::now()});
  }
  return datagrams;
}

void LoopbackReceiver::drain()
{
  std::vector<std::uint8_t> buffer(65536);
  while (recv(m_socket, buffer.data(), buffer.size(), MSG_DONTWAIT) >= 0) {
  }
}

} // namespace mocap::test
