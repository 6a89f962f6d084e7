#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <type_traits>
#include <utility>

namespace mocap {

/// The one seeded random number generator of the project: SplitMix64 (Steele, Lea & Flood 2014)
/// with its own derived draws. Every draw is plain integer and IEEE double arithmetic, so a seed
/// gives the same sequence on every platform and standard library (std::*_distribution and
/// std::shuffle are implementation-defined, mt19937 is not but is 2.5 kB of state). Not for
/// cryptography. Every member is O(1) unless said otherwise.
class Random
{
public:
  explicit Random(std::uint64_t seed) : m_state(seed) {}

  /// The next 64 uniform bits.
  std::uint64_t next()
  {
    std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }

  /// Uniform double in [0, 1): the top 53 bits of one draw, so every value is a multiple of 2^-53.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  /// Exactly uniform integer in [0, n), n ≥ 1: the draw modulo n, redrawn while it falls in the
  /// short bottom stretch that would bias it (probability < n / 2^64, so in practice one draw).
  template <typename Int>
  Int below(Int n)
  {
    static_assert(std::is_integral_v<Int>);
    return static_cast<Int>(belowUnsigned(static_cast<std::uint64_t>(n)));
  }

  /// Integer in [0, n), n ≥ 1, as ⌊uniform() · n⌋: always one draw, bias below n / 2^53. The draw
  /// k-means seeding, random marker selection and the tracking evaluation have always made, kept
  /// so their seeded results do not change; shuffle() uses it too.
  template <typename Int>
  Int index(Int n)
  {
    static_assert(std::is_integral_v<Int>);
    const auto k = static_cast<Int>(uniform() * static_cast<double>(n));
    return k < n ? k : n - 1;
  }

  /// Standard normal deviate (mean 0, variance 1) by the Box–Muller transform, which makes two
  /// per pair of uniform draws; the second is kept for the next call.
  double normal();

  /// Fisher–Yates (Durstenfeld) shuffle of [first, last): every permutation equally likely up to
  /// index()'s bias. O(last − first).
  template <typename RandomIt>
  void shuffle(RandomIt first, RandomIt last)
  {
    using std::swap;
    for (auto i = static_cast<std::size_t>(std::distance(first, last)); i > 1; --i)
      swap(first[static_cast<std::ptrdiff_t>(i - 1)], first[static_cast<std::ptrdiff_t>(index(i))]);
  }

private:
  std::uint64_t belowUnsigned(std::uint64_t n);

  std::uint64_t m_state;
  double m_spareNormal = 0.0;
  bool m_haveSpareNormal = false;
};

/// A seed for one of many independent streams: a hash of (seed, a, b), e.g. (user seed, k,
/// restart index), so each stream does not depend on which thread draws it or in what order.
[[nodiscard]] std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t a, std::uint64_t b);

} // namespace mocap
