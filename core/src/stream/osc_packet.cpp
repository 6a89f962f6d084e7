#include "mocap/stream/osc_packet.h"

#include "mocap/base/error.h"
#include "mocap/stream/network_bytes.h"

namespace mocap {

namespace {

constexpr std::string_view kBundleTag("#bundle\0", 8);
constexpr std::uint32_t kTimetagImmediately = 1;  // OSC's special timetag: 63 zero bits, then a one

void appendOscString(std::vector<std::uint8_t>& out, std::string_view text)
{
  appendBytes(out, text);
  const std::size_t padding = 4 - text.size() % 4;  // at least one NUL
  out.insert(out.end(), padding, 0);
}

[[noreturn]] void failOsc(const std::string& what)
{
  throw FormatError("OSC packet", what);
}

std::string readOscString(BigEndianReader& in, const char* field)
{
  std::string text;
  for (;;) {
    const std::optional<std::string_view> word = in.bytes(4);
    if (!word)
      failOsc(std::string("the ") + field + " runs past the end");
    const std::size_t nul = word->find('\0');
    text.append(*word, 0, nul);
    if (nul != std::string_view::npos)
      return text;
  }
}

void decodeMessage(BigEndianReader& in, std::vector<OscMessage>& out)
{
  OscMessage message;
  message.address = readOscString(in, "address");
  const std::string tags = readOscString(in, "type tags");
  if (tags.empty() || tags[0] != ',')
    failOsc("the message to " + message.address + " has no type tags");
  for (std::size_t i = 1; i < tags.size(); ++i) {
    if (tags[i] == 's') {
      message.arguments.emplace_back(readOscString(in, "string argument"));
    } else if (tags[i] == 'f' || tags[i] == 'i') {
      const std::optional<std::uint32_t> bits = in.u32();
      if (!bits)
        failOsc("an argument of " + message.address + " runs past the end");
      if (tags[i] == 'i') {
        message.arguments.emplace_back(static_cast<std::int32_t>(*bits));
      } else {
        float value = 0.0F;
        std::memcpy(&value, &*bits, sizeof value);
        message.arguments.emplace_back(value);
      }
    } else {
      failOsc(std::string("argument type '") + tags[i] + "' of " + message.address + " is not read");
    }
  }
  out.push_back(std::move(message));
}

void decodeElement(const std::uint8_t* data, std::size_t size, std::vector<OscMessage>& out, int depth)
{
  if (depth > 8)
    failOsc("bundles nest deeper than 8");
  BigEndianReader in(data, size);
  if (size >= kBundleTag.size() && std::string_view(reinterpret_cast<const char*>(data), 8) == kBundleTag) {
    (void)in.bytes(8);
    if (!in.bytes(8))
      failOsc("the bundle ends before its timetag");
    while (in.remaining() > 0) {
      const std::optional<std::uint32_t> elementSize = in.u32();
      if (!elementSize || *elementSize > in.remaining() || *elementSize % 4 != 0)
        failOsc("an element's size runs past the end of the bundle");
      decodeElement(data + in.offset(), *elementSize, out, depth + 1);
      (void)in.bytes(*elementSize);
    }
    return;
  }
  decodeMessage(in, out);
  if (in.remaining() != 0)
    failOsc(std::to_string(in.remaining()) + " bytes after the message to " + out.back().address);
}

} // namespace

OscBundleWriter::OscBundleWriter(std::vector<std::uint8_t>& out) : m_out(out)
{
  m_out.clear();
  appendBytes(m_out, kBundleTag);
  appendBigEndian32(m_out, 0);
  appendBigEndian32(m_out, kTimetagImmediately);
}

void OscBundleWriter::beginMessage(std::string_view address, std::string_view typeTags)
{
  m_sizeAt = m_out.size();
  appendBigEndian32(m_out, 0);  // the size, written by endMessage
  appendOscString(m_out, address);
  m_out.push_back(',');
  appendBytes(m_out, typeTags);
  const std::size_t padding = 4 - (typeTags.size() + 1) % 4;
  m_out.insert(m_out.end(), padding, 0);
}

void OscBundleWriter::addString(std::string_view text)
{
  appendOscString(m_out, text);
}

void OscBundleWriter::addFloat(float value)
{
  appendBigEndianFloat(m_out, value);
}

void OscBundleWriter::addInt(std::int32_t value)
{
  appendBigEndian32(m_out, static_cast<std::uint32_t>(value));
}

void OscBundleWriter::endMessage()
{
  const auto size = static_cast<std::uint32_t>(m_out.size() - m_sizeAt - 4);
  m_out[m_sizeAt] = static_cast<std::uint8_t>(size >> 24);
  m_out[m_sizeAt + 1] = static_cast<std::uint8_t>(size >> 16);
  m_out[m_sizeAt + 2] = static_cast<std::uint8_t>(size >> 8);
  m_out[m_sizeAt + 3] = static_cast<std::uint8_t>(size);
}

std::vector<OscMessage> decodeOscPacket(const std::uint8_t* data, std::size_t size)
{
  if (size == 0 || size % 4 != 0)
    failOsc("a packet's size must be a positive multiple of 4, not " + std::to_string(size));
  std::vector<OscMessage> messages;
  decodeElement(data, size, messages, 0);
  return messages;
}

} // namespace mocap
