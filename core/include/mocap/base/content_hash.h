#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace mocap {

/// A 64-bit hash of `bytes` that is the same on every platform and every run, to tell whether a
/// file or a text changed (batch --resume). Words of 8 bytes (little-endian) are mixed with a
/// multiply and a shift, the tail and the length last. Not cryptographic: it detects changes, not
/// tampering. O(#bytes), about 1 ns per 8 bytes.
[[nodiscard]] std::uint64_t contentHash(std::string_view bytes);

/// The hash as 16 lower-case hex digits, as reports record it. O(1).
[[nodiscard]] std::string hashText(std::uint64_t hash);

} // namespace mocap
