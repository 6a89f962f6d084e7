// The live stream's cost per frame (issue 34 target: < 20 µs, so streaming at 100 Hz adds nothing
// visible to playback): one frame encoded as Live Link Face's datagram and as a VMC bundle (52
// weights and 38 markers, the sample take's count), and encoded and sent over loopback to a bound
// socket. Reference in the same run: sending an empty datagram, the system call alone.
#include "mocap/stream/live_streamer.h"

#include <benchmark/benchmark.h>

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmath>

namespace {

constexpr Eigen::Index kFrames = 3000;
constexpr Eigen::Index kMarkers = 38;

std::shared_ptr<const mocap::StreamFrames> sampleFrames()
{
  static const auto frames = [] {
    auto f = std::make_shared<mocap::StreamFrames>();
    f->frameRate = 100.0;
    f->curves.resize(kFrames, 61);
    f->markers.resize(kFrames, 3 * kMarkers);
    for (Eigen::Index r = 0; r < kFrames; ++r) {
      for (Eigen::Index c = 0; c < 61; ++c)
        f->curves(r, c) = 0.5F + 0.5F * std::sin(0.01F * static_cast<float>(r + c));
      for (Eigen::Index c = 0; c < 3 * kMarkers; ++c)
        f->markers(r, c) = 0.1F * std::cos(0.01F * static_cast<float>(r + c));
    }
    for (Eigen::Index m = 0; m < kMarkers; ++m)
      f->markerNames.push_back("marker-" + std::to_string(m));
    return f;
  }();
  return frames;
}

/// A socket bound on loopback that nobody reads: the kernel takes the datagrams and drops them
/// once its buffer is full, as a receiver's would.
class SinkPort
{
public:
  SinkPort()
  {
    m_socket = socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    bind(m_socket, reinterpret_cast<sockaddr*>(&address), sizeof address);
    socklen_t size = sizeof address;
    getsockname(m_socket, reinterpret_cast<sockaddr*>(&address), &size);
    m_port = ntohs(address.sin_port);
  }
  ~SinkPort() { close(m_socket); }
  [[nodiscard]] int port() const { return m_port; }

private:
  int m_socket = -1;
  int m_port = 0;
};

mocap::StreamSettings settingsFor(mocap::StreamProtocol protocol, int port)
{
  mocap::StreamSettings settings;
  settings.protocol = protocol;
  settings.destination = {"127.0.0.1", port};
  settings.sendMarkers = protocol == mocap::StreamProtocol::Vmc;
  return settings;
}

void encodeFrames(benchmark::State& state, mocap::StreamProtocol protocol)
{
  mocap::StreamEncoder encoder(settingsFor(protocol, 9));
  const auto frames = sampleFrames();
  Eigen::Index row = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(encoder.encode(*frames, row).data());
    row = (row + 1) % kFrames;
  }
}

void encodeAndSend(benchmark::State& state, mocap::StreamProtocol protocol)
{
  const SinkPort sink;
  mocap::StreamEncoder encoder(settingsFor(protocol, sink.port()));
  mocap::UdpSender sender({"127.0.0.1", sink.port()});
  const auto frames = sampleFrames();
  Eigen::Index row = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sender.send(encoder.encode(*frames, row)));
    row = (row + 1) % kFrames;
  }
}

void BM_EncodeLiveLink(benchmark::State& state) { encodeFrames(state, mocap::StreamProtocol::LiveLink); }
void BM_EncodeVmcWithMarkers(benchmark::State& state) { encodeFrames(state, mocap::StreamProtocol::Vmc); }
void BM_SendLiveLink(benchmark::State& state) { encodeAndSend(state, mocap::StreamProtocol::LiveLink); }
void BM_SendVmcWithMarkers(benchmark::State& state) { encodeAndSend(state, mocap::StreamProtocol::Vmc); }

/// Reference: the system call alone, an empty datagram.
void BM_SendEmptyDatagram(benchmark::State& state)
{
  const SinkPort sink;
  mocap::UdpSender sender({"127.0.0.1", sink.port()});
  const std::vector<std::uint8_t> empty;
  for (auto _ : state)
    benchmark::DoNotOptimize(sender.send(empty));
}

BENCHMARK(BM_EncodeLiveLink)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EncodeVmcWithMarkers)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SendLiveLink)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SendVmcWithMarkers)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SendEmptyDatagram)->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
