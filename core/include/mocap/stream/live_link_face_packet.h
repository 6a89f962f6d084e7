#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// What one datagram of Live Link Face's stream holds. Epic has not published the layout; it is
/// the one Unreal's Live Link Face source reads and several independent public receivers decode
/// (all agree), pinned by a hand-written fixture in tests/core/live_link_face_packet_test.cpp.
struct LiveLinkFaceFrame
{
  static constexpr std::size_t kValues = 61;  ///< 52 ARKit weights, then head and eye rotations
  std::string deviceId;     ///< the app sends a 36-character UUID; some receivers assume that length
  std::string subject;      ///< the Live Link subject name the engine lists
  std::int32_t frame = 0;   ///< frame number at `rateNumerator / rateDenominator` frames per second
  float subFrame = 0.0F;    ///< fraction of a frame, [0, 1)
  std::int32_t rateNumerator = 60;
  std::int32_t rateDenominator = 1;
  std::array<float, kValues> values{};  ///< in liveLinkFacePacketNames() order
};

/// The packet's 61 value names in their order (Unreal's EARFaceBlendShape: JawLeft before
/// JawRight, unlike the app's CSV), rotations in radians last: HeadYaw, HeadPitch, HeadRoll,
/// LeftEyeYaw … RightEyeRoll.
[[nodiscard]] const std::array<std::string_view, LiveLinkFaceFrame::kValues>& liveLinkFacePacketNames();

/// The version byte of the layout below; receivers refuse others.
inline constexpr std::uint8_t kLiveLinkFacePacketVersion = 6;
/// Live Link Face's default UDP port.
inline constexpr int kLiveLinkFacePort = 11111;
/// The longest device id or subject name receivers take (Unreal reads at most 256 characters).
inline constexpr std::size_t kLiveLinkFaceMaxNameBytes = 255;

/// Encodes `frame` into `out` (cleared first; its capacity is reused, so a sender encoding every
/// frame allocates nothing after the first), big-endian throughout: version (uint8), device id
/// and subject (each a uint32 length and its bytes), frame (int32), sub-frame (float32), rate
/// numerator and denominator (int32), the value count (uint8, 61) and 61 float32. Throws
/// InvalidArgument for a device id or subject over 255 bytes (receivers cap both). O(#bytes).
void encodeLiveLinkFacePacket(const LiveLinkFaceFrame& frame, std::vector<std::uint8_t>& out);

/// Decodes a datagram as encodeLiveLinkFacePacket writes it (and the app sends it). Throws
/// FormatError ("Live Link Face packet") naming what is wrong: another version, a string running
/// past the end, a count other than 61, a size that disagrees. O(#bytes).
[[nodiscard]] LiveLinkFaceFrame decodeLiveLinkFacePacket(const std::uint8_t* data, std::size_t size);

} // namespace mocap
