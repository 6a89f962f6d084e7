#pragma once

#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>
#include <vector>

namespace mocap {

/// Appends `value` in network (big-endian) byte order, as Live Link Face and OSC send numbers. O(1).
inline void appendBigEndian32(std::vector<std::uint8_t>& out, std::uint32_t value)
{
  // One range insert, not four push_backs: a VMC frame with markers is ~1 400 such words.
  const std::uint8_t bytes[4] = {static_cast<std::uint8_t>(value >> 24), static_cast<std::uint8_t>(value >> 16),
                                 static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value)};
  out.insert(out.end(), bytes, bytes + 4);
}

/// An IEEE single's bits in network byte order. O(1).
inline void appendBigEndianFloat(std::vector<std::uint8_t>& out, float value)
{
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  appendBigEndian32(out, bits);
}

inline void appendBytes(std::vector<std::uint8_t>& out, std::string_view text)
{
  out.insert(out.end(), text.begin(), text.end());
}

/// Reads network-order fields from a datagram; each read returns nothing past the end (the
/// decoders turn that into an error naming the field). O(1) per read.
class BigEndianReader
{
public:
  BigEndianReader(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}

  [[nodiscard]] std::size_t offset() const { return m_offset; }
  [[nodiscard]] std::size_t remaining() const { return m_size - m_offset; }

  std::optional<std::uint8_t> byte()
  {
    if (remaining() < 1)
      return std::nullopt;
    return m_data[m_offset++];
  }

  std::optional<std::uint32_t> u32()
  {
    if (remaining() < 4)
      return std::nullopt;
    const std::uint8_t* p = m_data + m_offset;
    m_offset += 4;
    return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
  }

  std::optional<float> f32()
  {
    const std::optional<std::uint32_t> bits = u32();
    if (!bits)
      return std::nullopt;
    float value = 0.0F;
    std::memcpy(&value, &*bits, sizeof value);
    return value;
  }

  std::optional<std::string_view> bytes(std::size_t count)
  {
    if (remaining() < count)
      return std::nullopt;
    const std::string_view text(reinterpret_cast<const char*>(m_data + m_offset), count);
    m_offset += count;
    return text;
  }

private:
  const std::uint8_t* m_data;
  std::size_t m_size;
  std::size_t m_offset = 0;
};

} // namespace mocap
