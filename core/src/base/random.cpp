#include "mocap/base/random.h"

#include <cmath>

namespace mocap {

std::uint64_t Random::belowUnsigned(std::uint64_t n)
{
  // 2^64 mod n: the draws below it are the ones that would make small residues more likely.
  const std::uint64_t biased = (0 - n) % n;
  std::uint64_t draw = next();
  while (draw < biased)
    draw = next();
  return draw % n;
}

double Random::normal()
{
  if (m_haveSpareNormal) {
    m_haveSpareNormal = false;
    return m_spareNormal;
  }
  constexpr double kTwoPi = 6.28318530717958647692;
  const double radius = std::sqrt(-2.0 * std::log(1.0 - uniform()));  // 1 − u ∈ (0, 1]: finite log
  const double angle = kTwoPi * uniform();
  m_spareNormal = radius * std::sin(angle);
  m_haveSpareNormal = true;
  return radius * std::cos(angle);
}

std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t a, std::uint64_t b)
{
  Random first(seed);
  Random second(first.next() ^ (a * 0xD1B54A32D192ED03ULL));
  Random third(second.next() ^ (b * 0x8CB92BA72F3D8DD7ULL));
  return third.next();
}

} // namespace mocap
