// The live stream's wire formats: Live Link Face's datagram against a packet written by hand from
// the public description (field by field, offsets counted here), OSC bundles byte for byte, and
// the VMC frame's messages.
#include "mocap/stream/live_link_face_packet.h"
#include "mocap/stream/osc_packet.h"
#include "mocap/stream/vmc_packet.h"

#include "error_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace mocap {
namespace {

using test::errorOf;

/// Big-endian bytes of an IEEE single, written out by hand for the fixture.
void pushFloat(std::vector<std::uint8_t>& bytes, float value)
{
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, 4);
  for (int shift = 24; shift >= 0; shift -= 8)
    bytes.push_back(static_cast<std::uint8_t>(bits >> shift));
}

void pushText(std::vector<std::uint8_t>& bytes, const std::string& text)
{
  bytes.insert(bytes.end(), text.begin(), text.end());
}

const std::string kDevice = "0A1B2C3D-4E5F-4061-8273-94A5B6C7D8E9";  // 36 characters, as the app sends

/// The public description (receivers' sources, Unreal's FLiveLinkFacePacket): version byte 6;
/// device id as a big-endian uint32 length and its bytes; the subject name alike; frame number
/// (int32), sub-frame (float32), rate numerator and denominator (int32); a count byte (61) and 61
/// big-endian float32 values.
std::vector<std::uint8_t> handWrittenPacket()
{
  std::vector<std::uint8_t> bytes;
  bytes.push_back(6);                                 // offset 0: version
  pushText(bytes, std::string("\0\0\0\x24", 4));      // offset 1: device id length 36
  pushText(bytes, kDevice);                           // offset 5
  pushText(bytes, std::string("\0\0\0\x04", 4));      // offset 41: subject length 4
  pushText(bytes, "Face");                            // offset 45
  pushText(bytes, std::string("\0\0\x01\x2C", 4));    // offset 49: frame 300
  pushFloat(bytes, 0.0F);                             // offset 53: sub-frame
  pushText(bytes, std::string("\0\0\0\x3C", 4));      // offset 57: 60 …
  pushText(bytes, std::string("\0\0\0\x01", 4));      // offset 61: … per 1 second
  bytes.push_back(61);                                // offset 65: value count
  for (int i = 0; i < 61; ++i)                        // offset 66: the values, 4 bytes each
    pushFloat(bytes, static_cast<float>(i) / 100.0F);
  return bytes;                                       // 66 + 244 = 310 bytes
}

LiveLinkFaceFrame fixtureFrame()
{
  LiveLinkFaceFrame frame;
  frame.deviceId = kDevice;
  frame.subject = "Face";
  frame.frame = 300;
  frame.rateNumerator = 60;
  frame.rateDenominator = 1;
  for (std::size_t i = 0; i < frame.values.size(); ++i)
    frame.values[i] = static_cast<float>(i) / 100.0F;
  return frame;
}

TEST(LiveLinkFacePacket, MatchesAPacketWrittenByHandFromThePublicDescription)
{
  const std::vector<std::uint8_t> expected = handWrittenPacket();
  ASSERT_EQ(expected.size(), 310U);
  std::vector<std::uint8_t> ours;
  encodeLiveLinkFacePacket(fixtureFrame(), ours);
  ASSERT_EQ(ours.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    ASSERT_EQ(ours[i], expected[i]) << "byte " << i;
}

TEST(LiveLinkFacePacket, DecodesWhatItEncodesAndNamesItsValuesAsUnrealOrdersThem)
{
  std::vector<std::uint8_t> bytes;
  LiveLinkFaceFrame frame = fixtureFrame();
  frame.subFrame = 0.25F;
  frame.rateNumerator = 60000;
  frame.rateDenominator = 1001;
  encodeLiveLinkFacePacket(frame, bytes);
  const LiveLinkFaceFrame back = decodeLiveLinkFacePacket(bytes.data(), bytes.size());
  EXPECT_EQ(back.deviceId, kDevice);
  EXPECT_EQ(back.subject, "Face");
  EXPECT_EQ(back.frame, 300);
  EXPECT_EQ(back.subFrame, 0.25F);
  EXPECT_EQ(back.rateNumerator, 60000);
  EXPECT_EQ(back.rateDenominator, 1001);
  EXPECT_EQ(back.values, frame.values);
  const auto& names = liveLinkFacePacketNames();
  EXPECT_EQ(names[15], "JawLeft");  // the app's CSV lists JawRight first; the packet does not
  EXPECT_EQ(names[16], "JawRight");
  EXPECT_EQ(names[51], "TongueOut");
  EXPECT_EQ(names[52], "HeadYaw");
  EXPECT_EQ(names[60], "RightEyeRoll");
}

TEST(LiveLinkFacePacket, ABrokenDatagramIsAClearErrorNeverARead)
{
  std::vector<std::uint8_t> bytes = handWrittenPacket();
  EXPECT_NE(errorOf([&] { (void)decodeLiveLinkFacePacket(bytes.data(), 0); }).find("empty"), std::string::npos);
  EXPECT_NE(errorOf([&] { (void)decodeLiveLinkFacePacket(bytes.data(), 30); }).find("device id"), std::string::npos);
  EXPECT_NE(errorOf([&] { (void)decodeLiveLinkFacePacket(bytes.data(), bytes.size() - 1); }).find("244"),
            std::string::npos);
  bytes[0] = 5;
  EXPECT_NE(errorOf([&] { (void)decodeLiveLinkFacePacket(bytes.data(), bytes.size()); }).find("version 5"),
            std::string::npos);
  bytes = handWrittenPacket();
  bytes[1] = 0x7F;  // a length of two gigabytes
  EXPECT_NE(errorOf([&] { (void)decodeLiveLinkFacePacket(bytes.data(), bytes.size()); }).find("at most 255"),
            std::string::npos);
  LiveLinkFaceFrame long_name = fixtureFrame();
  long_name.subject.assign(300, 'x');
  EXPECT_NE(errorOf([&] { encodeLiveLinkFacePacket(long_name, bytes); }).find("255"), std::string::npos);
}

TEST(OscPacket, WritesABundleAsOsc10SpellsIt)
{
  std::vector<std::uint8_t> bytes;
  OscBundleWriter bundle(bytes);
  bundle.beginMessage("/a", "sf");
  bundle.addString("abc");
  bundle.addFloat(1.0F);
  bundle.endMessage();
  // "#bundle\0", timetag 1 ("immediately"), then the message's size (16) and the message:
  // "/a\0\0" ",sf\0" "abc\0" and 1.0f big-endian.
  const std::vector<std::uint8_t> expected = {
      '#', 'b', 'u', 'n', 'd', 'l', 'e', 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 16,
      '/', 'a', 0,   0,   ',', 's', 'f', 0, 'a', 'b', 'c', 0, 0x3F, 0x80, 0, 0};
  EXPECT_EQ(bytes, expected);
  const std::vector<OscMessage> messages = decodeOscPacket(bytes.data(), bytes.size());
  ASSERT_EQ(messages.size(), 1U);
  EXPECT_EQ(messages[0].address, "/a");
  ASSERT_EQ(messages[0].arguments.size(), 2U);
  EXPECT_EQ(std::get<std::string>(messages[0].arguments[0]), "abc");
  EXPECT_EQ(std::get<float>(messages[0].arguments[1]), 1.0F);
}

TEST(OscPacket, AStringOfAWholeWordStillEndsInFourNuls)
{
  std::vector<std::uint8_t> bytes;
  OscBundleWriter bundle(bytes);
  bundle.beginMessage("/abc", "is");
  bundle.addInt(-2);
  bundle.addString("wxyz");
  bundle.endMessage();
  EXPECT_EQ(bytes.size(), 16U + 4U + 8U + 4U + 4U + 8U);
  const std::vector<OscMessage> messages = decodeOscPacket(bytes.data(), bytes.size());
  ASSERT_EQ(messages.size(), 1U);
  EXPECT_EQ(std::get<std::int32_t>(messages[0].arguments[0]), -2);
  EXPECT_EQ(std::get<std::string>(messages[0].arguments[1]), "wxyz");
  bytes.resize(bytes.size() - 4);
  EXPECT_NE(errorOf([&] { (void)decodeOscPacket(bytes.data(), bytes.size()); }).find("OSC packet"), std::string::npos);
}

TEST(VmcPacket, SendsEveryWeightThenApplyThenEachMarkerWithASample)
{
  const std::vector<std::string> names = {"JawOpen", "EyeBlinkLeft"};
  const Eigen::RowVector2f values(0.5F, 0.25F);
  const std::vector<std::string> markers = {"nose", "chin"};
  Eigen::RowVectorXf positions(6);
  positions << 0.1F, 0.2F, 0.3F, NAN, 0.0F, 0.0F;  // the chin is missing at this frame
  std::vector<std::uint8_t> bytes;
  encodeVmcFrame(names, values, markers, positions, bytes);
  const std::vector<OscMessage> messages = decodeOscPacket(bytes.data(), bytes.size());
  ASSERT_EQ(messages.size(), 4U);
  EXPECT_EQ(messages[0].address, "/VMC/Ext/Blend/Val");
  EXPECT_EQ(std::get<std::string>(messages[0].arguments[0]), "JawOpen");
  EXPECT_EQ(std::get<float>(messages[0].arguments[1]), 0.5F);
  EXPECT_EQ(std::get<std::string>(messages[1].arguments[0]), "EyeBlinkLeft");
  EXPECT_EQ(messages[2].address, "/VMC/Ext/Blend/Apply");
  EXPECT_TRUE(messages[2].arguments.empty());
  EXPECT_EQ(messages[3].address, "/VMC/Ext/Tra/Pos");
  ASSERT_EQ(messages[3].arguments.size(), 8U);
  EXPECT_EQ(std::get<std::string>(messages[3].arguments[0]), "nose");
  EXPECT_EQ(std::get<float>(messages[3].arguments[3]), 0.3F);
  EXPECT_EQ(std::get<float>(messages[3].arguments[7]), 1.0F);  // identity rotation's w
  EXPECT_FALSE(errorOf([&] { encodeVmcFrame(names, Eigen::RowVector3f::Zero(), {}, Eigen::RowVectorXf(), bytes); }).empty());
}

} // namespace
} // namespace mocap
