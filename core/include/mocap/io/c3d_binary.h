#pragma once

#include <cstdint>
#include <cstring>
#include <string>

namespace mocap::c3d {

/// Processor type byte of the parameter section: it fixes byte order and float format.
enum class Processor : std::uint8_t
{
  Intel = 84,  ///< little-endian, IEEE floats
  Dec = 85,    ///< little-endian integers, VAX F-floats
  Mips = 86,   ///< big-endian, IEEE floats
};

/// Bytes in a C3D block; header, parameter and data sections start on block boundaries.
inline constexpr std::size_t kBlockSize = 512;
/// Second header byte and second parameter-section byte of every C3D file.
inline constexpr std::uint8_t kKeyByte = 0x50;
/// Marks the header's event section as holding 4-character labels.
inline constexpr std::uint16_t kEventKey = 12345;

[[nodiscard]] inline std::uint16_t readU16(const unsigned char* p, Processor processor)
{
  if (processor == Processor::Mips)
    return static_cast<std::uint16_t>((p[0] << 8) | p[1]);
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}

[[nodiscard]] inline std::int16_t readI16(const unsigned char* p, Processor processor)
{
  return static_cast<std::int16_t>(readU16(p, processor));
}

/// A VAX F-float has the bit layout of an IEEE single with its two 16-bit words swapped and an
/// exponent bias two higher, so after the swap, lowering the exponent by 2 gives the exact value.
[[nodiscard]] inline float decodeVaxFloat(const unsigned char* p)
{
  std::uint32_t bits = (std::uint32_t{p[1]} << 24) | (std::uint32_t{p[0]} << 16) |
                       (std::uint32_t{p[3]} << 8) | std::uint32_t{p[2]};
  const std::uint32_t exponent = (bits >> 23) & 0xFFu;
  if (exponent <= 2)
    return 0.0f;  // VAX zero, reserved operands and values below float range
  bits -= (2u << 23);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

[[nodiscard]] inline float readF32(const unsigned char* p, Processor processor)
{
  std::uint32_t bits = 0;
  switch (processor) {
  case Processor::Intel:
    std::memcpy(&bits, p, 4);  // the library targets little-endian hosts (checked in c3d_reader.cpp)
    break;
  case Processor::Mips:
    bits = (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
           std::uint32_t{p[3]};
    break;
  case Processor::Dec:
    return decodeVaxFloat(p);
  }
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

/// Little-endian (Intel) encoders for the writer.
inline void appendU8(std::string& out, std::uint8_t v)
{
  out.push_back(static_cast<char>(v));
}

inline void appendI16(std::string& out, std::int16_t v)
{
  const auto u = static_cast<std::uint16_t>(v);
  out.push_back(static_cast<char>(u & 0xFFu));
  out.push_back(static_cast<char>(u >> 8));
}

inline void appendF32(std::string& out, float v)
{
  char bytes[4];
  std::memcpy(bytes, &v, 4);
  out.append(bytes, 4);
}

inline void putI16(std::string& out, std::size_t at, std::int16_t v)
{
  const auto u = static_cast<std::uint16_t>(v);
  out[at] = static_cast<char>(u & 0xFFu);
  out[at + 1] = static_cast<char>(u >> 8);
}

inline void putF32(std::string& out, std::size_t at, float v)
{
  std::memcpy(&out[at], &v, 4);
}

} // namespace mocap::c3d
