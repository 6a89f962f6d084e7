#include "mocap/base/content_hash.h"

namespace mocap {

namespace {

constexpr std::uint64_t kMultiplier = 0x9E3779B97F4A7C15ULL;  // 2^64 / golden ratio, odd

std::uint64_t mix(std::uint64_t h, std::uint64_t word)
{
  h = (h ^ word) * kMultiplier;
  return h ^ (h >> 29);
}

/// Bytes [0, n) of `p` (n ≤ 8) as a little-endian word, whatever the machine's byte order.
std::uint64_t littleEndian(const unsigned char* p, std::size_t n)
{
  std::uint64_t word = 0;
  for (std::size_t i = n; i-- > 0;)
    word = (word << 8) | p[i];
  return word;
}

} // namespace

std::uint64_t contentHash(std::string_view bytes)
{
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::size_t n = bytes.size();
  std::uint64_t h = 0x6A09E667F3BCC908ULL;
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8)
    h = mix(h, littleEndian(p + i, 8));
  h = mix(h, littleEndian(p + i, n - i));
  h = mix(h, static_cast<std::uint64_t>(n));
  return mix(h, h >> 32);
}

std::string hashText(std::uint64_t hash)
{
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string text(16, '0');
  for (int i = 15; i >= 0; --i, hash >>= 4)
    text[static_cast<std::size_t>(i)] = kDigits[hash & 15U];
  return text;
}

} // namespace mocap
