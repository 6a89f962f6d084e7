#include "mocap/stream/live_link_face_packet.h"

#include "mocap/base/error.h"
#include "mocap/stream/network_bytes.h"

namespace mocap {

namespace {

[[noreturn]] void failPacket(const std::string& what)
{
  throw FormatError("Live Link Face packet", what);
}

void appendString(std::vector<std::uint8_t>& out, std::string_view text, const char* field)
{
  if (text.size() > kLiveLinkFaceMaxNameBytes)
    throw InvalidArgument(std::string("Live Link Face: the ") + field + " has " + std::to_string(text.size()) +
                          " bytes; receivers take at most 255");
  appendBigEndian32(out, static_cast<std::uint32_t>(text.size()));
  appendBytes(out, text);
}

std::string readString(BigEndianReader& in, const char* field)
{
  const std::optional<std::uint32_t> length = in.u32();
  if (!length)
    failPacket(std::string("it ends before the ") + field + "'s length");
  if (*length > kLiveLinkFaceMaxNameBytes)
    failPacket(std::string("the ") + field + " claims " + std::to_string(*length) + " bytes (at most 255)");
  const std::optional<std::string_view> text = in.bytes(*length);
  if (!text)
    failPacket(std::string("the ") + field + " runs past the end of the datagram");
  return std::string(*text);
}

std::int32_t readInt(BigEndianReader& in, const char* field)
{
  const std::optional<std::uint32_t> value = in.u32();
  if (!value)
    failPacket(std::string("it ends before the ") + field);
  return static_cast<std::int32_t>(*value);
}

} // namespace

const std::array<std::string_view, LiveLinkFaceFrame::kValues>& liveLinkFacePacketNames()
{
  static constexpr std::array<std::string_view, LiveLinkFaceFrame::kValues> names = {
      "EyeBlinkLeft",       "EyeLookDownLeft",     "EyeLookInLeft",     "EyeLookOutLeft",    "EyeLookUpLeft",
      "EyeSquintLeft",      "EyeWideLeft",         "EyeBlinkRight",     "EyeLookDownRight",  "EyeLookInRight",
      "EyeLookOutRight",    "EyeLookUpRight",      "EyeSquintRight",    "EyeWideRight",      "JawForward",
      "JawLeft",            "JawRight",            "JawOpen",           "MouthClose",        "MouthFunnel",
      "MouthPucker",        "MouthLeft",           "MouthRight",        "MouthSmileLeft",    "MouthSmileRight",
      "MouthFrownLeft",     "MouthFrownRight",     "MouthDimpleLeft",   "MouthDimpleRight",  "MouthStretchLeft",
      "MouthStretchRight",  "MouthRollLower",      "MouthRollUpper",    "MouthShrugLower",   "MouthShrugUpper",
      "MouthPressLeft",     "MouthPressRight",     "MouthLowerDownLeft", "MouthLowerDownRight", "MouthUpperUpLeft",
      "MouthUpperUpRight",  "BrowDownLeft",        "BrowDownRight",     "BrowInnerUp",       "BrowOuterUpLeft",
      "BrowOuterUpRight",   "CheekPuff",           "CheekSquintLeft",   "CheekSquintRight",  "NoseSneerLeft",
      "NoseSneerRight",     "TongueOut",           "HeadYaw",           "HeadPitch",         "HeadRoll",
      "LeftEyeYaw",         "LeftEyePitch",        "LeftEyeRoll",       "RightEyeYaw",       "RightEyePitch",
      "RightEyeRoll"};
  return names;
}

void encodeLiveLinkFacePacket(const LiveLinkFaceFrame& frame, std::vector<std::uint8_t>& out)
{
  out.clear();
  out.push_back(kLiveLinkFacePacketVersion);
  appendString(out, frame.deviceId, "device id");
  appendString(out, frame.subject, "subject name");
  appendBigEndian32(out, static_cast<std::uint32_t>(frame.frame));
  appendBigEndianFloat(out, frame.subFrame);
  appendBigEndian32(out, static_cast<std::uint32_t>(frame.rateNumerator));
  appendBigEndian32(out, static_cast<std::uint32_t>(frame.rateDenominator));
  out.push_back(static_cast<std::uint8_t>(LiveLinkFaceFrame::kValues));
  for (const float value : frame.values)
    appendBigEndianFloat(out, value);
}

LiveLinkFaceFrame decodeLiveLinkFacePacket(const std::uint8_t* data, std::size_t size)
{
  BigEndianReader in(data, size);
  const std::optional<std::uint8_t> version = in.byte();
  if (!version)
    failPacket("the datagram is empty");
  if (*version != kLiveLinkFacePacketVersion)
    failPacket("version " + std::to_string(*version) + ", not " + std::to_string(kLiveLinkFacePacketVersion));
  LiveLinkFaceFrame frame;
  frame.deviceId = readString(in, "device id");
  frame.subject = readString(in, "subject name");
  frame.frame = readInt(in, "frame number");
  const std::optional<float> subFrame = in.f32();
  if (!subFrame)
    failPacket("it ends before the sub-frame");
  frame.subFrame = *subFrame;
  frame.rateNumerator = readInt(in, "frame rate");
  frame.rateDenominator = readInt(in, "frame rate's denominator");
  const std::optional<std::uint8_t> count = in.byte();
  if (!count)
    failPacket("it ends before the value count");
  if (*count != LiveLinkFaceFrame::kValues)
    failPacket(std::to_string(*count) + " values, not 61");
  if (in.remaining() != 4 * LiveLinkFaceFrame::kValues)
    failPacket(std::to_string(in.remaining()) + " bytes after the count, not the 244 of 61 floats");
  for (float& value : frame.values)
    value = *in.f32();
  return frame;
}

} // namespace mocap
