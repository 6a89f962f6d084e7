#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace mocap {

/// Writes one OSC 1.0 bundle (timetag "immediately") into a reused buffer: `#bundle`, the
/// timetag, then each message as its int32 size and the message: the address and the type tags as
/// OSC strings (NUL-terminated, padded to 4 bytes), then the arguments big-endian. Building into
/// the caller's buffer keeps a per-frame sender free of allocation once the buffer has grown.
/// O(#bytes).
class OscBundleWriter
{
public:
  /// Clears `out` and writes the bundle's header into it.
  explicit OscBundleWriter(std::vector<std::uint8_t>& out);

  /// Starts a message; `typeTags` lists the arguments to follow without the leading comma
  /// ("sf": a string then a float; "" for none).
  void beginMessage(std::string_view address, std::string_view typeTags);
  void addString(std::string_view text);
  void addFloat(float value);
  void addInt(std::int32_t value);
  /// Ends the message: writes its size in front of it.
  void endMessage();

private:
  std::vector<std::uint8_t>& m_out;
  std::size_t m_sizeAt = 0;
};

/// One decoded OSC message: its address and arguments (s, f and i only).
struct OscMessage
{
  std::string address;
  std::vector<std::variant<std::string, float, std::int32_t>> arguments;
};

/// The messages of an OSC packet (a bundle, nested bundles flattened, or one message). Throws
/// FormatError ("OSC packet") for a malformed packet or an argument type other than s, f, i.
/// O(#bytes).
[[nodiscard]] std::vector<OscMessage> decodeOscPacket(const std::uint8_t* data, std::size_t size);

} // namespace mocap
