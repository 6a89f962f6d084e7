// The live streamer end to end on loopback: a receiver in the test decodes every datagram (frame
// numbers in order, values as sent, subject and rate), measures when each arrived against its due
// time, and the errors a user can run into (a closed port, a host that does not resolve, absurd
// rates, nothing to send) are clear and never crash.
#include "mocap/stream/live_link_face_packet.h"
#include "mocap/stream/live_streamer.h"
#include "mocap/stream/osc_packet.h"

#include "error_text.h"
#include "loopback_receiver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include <thread>

namespace mocap {
namespace {

using test::errorOf;
using test::LoopbackReceiver;
using Clock = std::chrono::steady_clock;

/// Frames whose 61 values tell the frame and the column apart: frame f, column c holds f + c / 100.
std::shared_ptr<const StreamFrames> numberedFrames(Eigen::Index count, double rate)
{
  auto frames = std::make_shared<StreamFrames>();
  frames->frameRate = rate;
  frames->firstFrame = 1000;
  frames->curves.resize(count, 61);
  for (Eigen::Index f = 0; f < count; ++f)
    for (Eigen::Index c = 0; c < 61; ++c)
      frames->curves(f, c) = static_cast<float>(f) + static_cast<float>(c) / 100.0F;
  return frames;
}

StreamSettings liveLinkTo(int port)
{
  StreamSettings settings;
  settings.destination = {"127.0.0.1", port};
  settings.subject = "TestFace";
  return settings;
}

TEST(LiveStreamer, EveryFrameOfATakeReachesALiveLinkReceiverInOrderAndOnTime)
{
  LoopbackReceiver receiver;
  const double rate = 100.0;
  const auto frames = numberedFrames(150, rate);
  LiveStreamer streamer(liveLinkTo(receiver.port()), frames);
  streamer.playRange(0, 149, false);
  const std::vector<LoopbackReceiver::Datagram> got = receiver.receive(150);
  streamer.wait();
  ASSERT_EQ(got.size(), 150U);
  std::vector<double> lateMs;
  for (std::size_t i = 0; i < got.size(); ++i) {
    const LiveLinkFaceFrame frame = decodeLiveLinkFacePacket(got[i].bytes.data(), got[i].bytes.size());
    ASSERT_EQ(frame.frame, 1000 + static_cast<std::int32_t>(i));
    EXPECT_EQ(frame.subject, "TestFace");
    EXPECT_EQ(frame.deviceId.size(), 36U);
    EXPECT_EQ(frame.rateNumerator, 100);
    EXPECT_EQ(frame.rateDenominator, 1);
    for (std::size_t c = 0; c < 61; ++c)
      ASSERT_NEAR(frame.values[c], frames->curves(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(c)), 1e-6);
    const auto due = streamer.startTime() + std::chrono::duration_cast<Clock::duration>(
                                                std::chrono::duration<double>(static_cast<double>(i) / rate));
    lateMs.push_back(std::chrono::duration<double, std::milli>(got[i].arrived - due).count());
  }
  std::vector<double> sorted = lateMs;
  std::sort(sorted.begin(), sorted.end());
  const double p95 = sorted[static_cast<std::size_t>(0.95 * static_cast<double>(sorted.size()))];
  // The figure the issue asks for (target 2 ms); the bound is loose so a loaded CI machine (or a
  // sanitizer build) does not fail it, but a sender that waits on anything but its clock does.
  std::cout << "[ measured ] Live Link on loopback: arrival after the due time " << sorted.front() << " ms min, "
            << sorted[sorted.size() / 2] << " ms median, " << p95 << " ms p95, " << sorted.back() << " ms max\n";
  EXPECT_GE(sorted.front(), -0.5) << "a datagram left before its time";
  EXPECT_LT(p95, 20.0);
  const StreamStats stats = streamer.stats();
  EXPECT_EQ(stats.sent, 150);
  EXPECT_EQ(stats.failed, 0);
}

TEST(LiveStreamer, AnotherRateResamplesTheTakeSoItStillPlaysAtItsSpeed)
{
  LoopbackReceiver receiver;
  const auto frames = numberedFrames(40, 200.0);  // 0.2 s of take
  StreamSettings settings = liveLinkTo(receiver.port());
  settings.rate = 50.0;  // every fourth frame
  LiveStreamer streamer(settings, frames);
  streamer.playRange(0, 39, false);
  const std::vector<LoopbackReceiver::Datagram> got = receiver.receive(100);
  ASSERT_EQ(got.size(), 10U);
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_EQ(decodeLiveLinkFacePacket(got[i].bytes.data(), got[i].bytes.size()).frame,
              1000 + 4 * static_cast<std::int32_t>(i));
}

TEST(LiveStreamer, FollowingSendsTheCurrentFrameAsItMovesAndStopsAtOnce)
{
  LoopbackReceiver receiver;
  const auto frames = numberedFrames(10, 100.0);
  LiveStreamer streamer(liveLinkTo(receiver.port()), frames);
  streamer.setCurrentFrame(3);
  streamer.followCurrentFrame();
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  streamer.setCurrentFrame(7);
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  const auto before = Clock::now();
  streamer.stop();
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - before).count(), 0.1);
  EXPECT_FALSE(streamer.running());
  const std::vector<LoopbackReceiver::Datagram> got = receiver.receive(1000);
  ASSERT_GE(got.size(), 6U);
  EXPECT_EQ(decodeLiveLinkFacePacket(got.front().bytes.data(), got.front().bytes.size()).frame, 1003);
  EXPECT_EQ(decodeLiveLinkFacePacket(got.back().bytes.data(), got.back().bytes.size()).frame, 1007);
}

TEST(LiveStreamer, VmcCarriesTheWeightsUnderArkitNamesAndTheMarkersInMetres)
{
  LoopbackReceiver receiver;
  auto frames = std::make_shared<StreamFrames>(*numberedFrames(3, 60.0));
  Take take({"nose", "chin"}, 3, 60.0);
  take.setUnits(LengthUnit::Millimetre);
  for (Eigen::Index f = 0; f < 3; ++f) {
    take.setPosition(f, 0, Eigen::Vector3d(1000.0, 20.0, 3.0));
    take.valid()(f, 0) = true;
  }
  addStreamMarkers(*frames, take);
  StreamSettings settings;
  settings.protocol = StreamProtocol::Vmc;
  settings.destination = {"127.0.0.1", receiver.port()};
  settings.sendMarkers = true;
  LiveStreamer streamer(settings, frames);
  streamer.playRange(0, 2, false);
  const std::vector<LoopbackReceiver::Datagram> got = receiver.receive(3);
  ASSERT_EQ(got.size(), 3U);
  const std::vector<OscMessage> messages = decodeOscPacket(got[2].bytes.data(), got[2].bytes.size());
  ASSERT_EQ(messages.size(), 52U + 1U + 1U);  // 52 weights, Apply, the nose (the chin has no sample)
  EXPECT_EQ(std::get<std::string>(messages[17].arguments[0]), "JawOpen");
  EXPECT_NEAR(std::get<float>(messages[17].arguments[1]), 2.17F, 1e-6);
  EXPECT_EQ(messages[52].address, "/VMC/Ext/Blend/Apply");
  EXPECT_EQ(std::get<std::string>(messages[53].arguments[0]), "nose");
  EXPECT_NEAR(std::get<float>(messages[53].arguments[1]), 1.0F, 1e-6);    // 1000 mm
  EXPECT_NEAR(std::get<float>(messages[53].arguments[2]), 0.02F, 1e-6);   // 20 mm
}

TEST(LiveStreamer, AClosedPortIsReportedAndTheStreamGoesOn)
{
  int port = 0;
  {
    LoopbackReceiver closed;  // a port that was free a moment ago, and is closed again
    port = closed.port();
  }
  LiveStreamer streamer(liveLinkTo(port), numberedFrames(20, 200.0));
  streamer.playRange(0, 19, false);
  streamer.wait();
  const StreamStats stats = streamer.stats();
  EXPECT_GT(stats.failed, 0);
  EXPECT_EQ(stats.sent + stats.failed, 20);
  EXPECT_NE(stats.lastError.find("nothing listens on 127.0.0.1:" + std::to_string(port)), std::string::npos)
      << stats.lastError;
}

TEST(LiveStreamer, BadSettingsAreClearErrorsBeforeAnythingIsSent)
{
  const auto frames = numberedFrames(5, 60.0);
  StreamSettings settings = liveLinkTo(9);
  settings.rate = 10000.0;
  EXPECT_NE(errorOf([&] { LiveStreamer s(settings, frames); }).find("at most 1000 Hz"), std::string::npos);
  settings.rate = -1.0;
  EXPECT_NE(errorOf([&] { LiveStreamer s(settings, frames); }).find("above 0"), std::string::npos);
  settings.rate = 0.0;
  settings.destination.host = "no-such-host.invalid";
  EXPECT_NE(errorOf([&] { LiveStreamer s(settings, frames); }).find("cannot resolve host 'no-such-host.invalid'"),
            std::string::npos);
  settings.destination.host = "127.0.0.1";
  auto markersOnly = std::make_shared<StreamFrames>();
  markersOnly->frameRate = 60.0;
  markersOnly->markerNames = {"nose"};
  markersOnly->markers = StreamMatrix::Zero(5, 3);
  EXPECT_NE(errorOf([&] { LiveStreamer s(settings, markersOnly); }).find("solve the take to a rig first"),
            std::string::npos);
  settings.sendMarkers = true;
  EXPECT_NE(errorOf([&] { LiveStreamer s(settings, frames); }).find("over VMC"), std::string::npos);
  LiveStreamer streamer(liveLinkTo(9), frames);
  EXPECT_NE(errorOf([&] { streamer.playRange(0, 5, false); }).find("not within the 5 frames"), std::string::npos);
}

TEST(StreamDestination, ReadsHostAndPortAndRefusesWhatIsNot)
{
  EXPECT_EQ(parseStreamDestination("10.0.0.2:9000", 11111).port, 9000);
  EXPECT_EQ(parseStreamDestination("studio-pc", 11111).host, "studio-pc");
  EXPECT_EQ(parseStreamDestination("studio-pc", 11111).port, 11111);
  EXPECT_EQ(parseStreamDestination("[::1]:39539", 11111).host, "::1");
  EXPECT_EQ(parseStreamDestination("::1", 11111).host, "::1");
  EXPECT_EQ(describeDestination({"::1", 5}), "[::1]:5");
  EXPECT_NE(errorOf([] { (void)parseStreamDestination("host:0", 1); }).find("1…65535"), std::string::npos);
  EXPECT_NE(errorOf([] { (void)parseStreamDestination("host:99999", 1); }).find("1…65535"), std::string::npos);
  EXPECT_NE(errorOf([] { (void)parseStreamDestination(":5", 1); }).find("names no host"), std::string::npos);
  EXPECT_NE(errorOf([] { (void)parseStreamDestination("host:x", 1); }).find("not a port"), std::string::npos);
}

} // namespace
} // namespace mocap
