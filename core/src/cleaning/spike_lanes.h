#pragma once
// Two neighbouring windows at once, one per lane of an SSE2 register (a portable pair of doubles
// without SSE2), for the robust spike detector's stages. Everything has internal linkage, as in
// median_networks.h: only the baseline units include it, never the AVX2 kernels' unit.

#include "median_networks.h"
#include "spike_detector_parts.h"

#include <Eigen/Core>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

namespace mocap {
namespace {

// The same medians for kLanes neighbouring windows at once (one window per lane of a vector
// register): each lane goes through the very operations of the scalar code, so the results are
// the scalar results bit for bit. std::min(a, b) is minsd with b first and std::max(a, b) maxsd
// with b first, which is what the vector forms below do (the same answer for equal or signed zeros).
#if defined(__SSE2__)
constexpr Eigen::Index kLanes = 2;
struct Lanes
{
  __m128d v;
};
inline Lanes loadLanes(const double* p)
{
  return {_mm_loadu_pd(p)};
}
inline double lane(const Lanes& a, std::size_t l)
{
  alignas(16) double values[kLanes];
  _mm_store_pd(values, a.v);
  return values[l];
}
inline Lanes makeLanes(double first, double second)
{
  return {_mm_set_pd(second, first)};
}
inline Lanes operator+(const Lanes& a, const Lanes& b)
{
  return {_mm_add_pd(a.v, b.v)};
}
inline Lanes operator*(const Lanes& a, const Lanes& b)
{
  return {_mm_mul_pd(a.v, b.v)};
}
inline Lanes operator/(const Lanes& a, const Lanes& b)
{
  return {_mm_div_pd(a.v, b.v)};
}
inline Lanes squareRoot(const Lanes& a)
{
  return {_mm_sqrt_pd(a.v)};
}
inline void storeLanes(double* p, const Lanes& a)
{
  _mm_storeu_pd(p, a.v);
}
inline Lanes operator-(const Lanes& a, const Lanes& b)
{
  return {_mm_sub_pd(a.v, b.v)};
}
inline Lanes operator*(double a, const Lanes& b)
{
  return {_mm_mul_pd(_mm_set1_pd(a), b.v)};
}
inline Lanes operator*(const Lanes& a, double b)
{
  return {_mm_mul_pd(a.v, _mm_set1_pd(b))};
}
inline void order(Lanes& a, Lanes& b)
{
  const __m128d low = _mm_min_pd(b.v, a.v);
  b.v = _mm_max_pd(b.v, a.v);
  a.v = low;
}
#else
constexpr Eigen::Index kLanes = 2;
struct Lanes
{
  std::array<double, static_cast<std::size_t>(kLanes)> v;
};
inline Lanes loadLanes(const double* p)
{
  return {{p[0], p[1]}};
}
inline double lane(const Lanes& a, std::size_t l)
{
  return a.v[l];
}
template <typename Op>
inline Lanes each(const Lanes& a, const Lanes& b, Op op)
{
  Lanes r;
  for (std::size_t l = 0; l < static_cast<std::size_t>(kLanes); ++l)
    r.v[l] = op(a.v[l], b.v[l]);
  return r;
}
inline Lanes makeLanes(double first, double second)
{
  return {{first, second}};
}
inline Lanes operator+(const Lanes& a, const Lanes& b)
{
  return each(a, b, [](double x, double y) { return x + y; });
}
inline Lanes operator*(const Lanes& a, const Lanes& b)
{
  return each(a, b, [](double x, double y) { return x * y; });
}
inline Lanes operator/(const Lanes& a, const Lanes& b)
{
  return each(a, b, [](double x, double y) { return x / y; });
}
inline Lanes squareRoot(const Lanes& a)
{
  return each(a, a, [](double x, double /*unused*/) { return std::sqrt(x); });
}
inline void storeLanes(double* p, const Lanes& a)
{
  p[0] = a.v[0];
  p[1] = a.v[1];
}
inline Lanes operator-(const Lanes& a, const Lanes& b)
{
  return each(a, b, [](double x, double y) { return x - y; });
}
inline Lanes operator*(double a, const Lanes& b)
{
  return each({{a, a}}, b, [](double x, double y) { return x * y; });
}
inline Lanes operator*(const Lanes& a, double b)
{
  return each(a, {{b, b}}, [](double x, double y) { return x * y; });
}
inline void order(Lanes& a, Lanes& b)
{
  for (std::size_t l = 0; l < static_cast<std::size_t>(kLanes); ++l)
    order(a.v[l], b.v[l]);
}
#endif

// Calls f(std::integral_constant<std::size_t, k>{}) for k = 0..N−1, unrolled at compile time so
// the lanes of the networks below stay in registers (-O2 does not unroll these loops).
template <typename F, std::size_t... K>
void unrolledSequence(F& f, std::index_sequence<K...> /*unused*/)
{
  (f(std::integral_constant<std::size_t, K>{}), ...);
}

template <std::size_t N, typename F>
void unrolled(F&& f)
{
  unrolledSequence(f, std::make_index_sequence<N>{});
}

using spikes::Trajectory;

// |sample − estimate|² for the kLanes samples from frame i (the estimate one Lanes per axis),
// the squares summed as Eigen's norm() sums a 3-vector, x² + (y² + z²), so each lane's square
// root is the scalar norm bit for bit. The roots are taken later, a whole run at a time
// (rootsOf): one root per call here waited out the square root's latency every two samples,
// a fifth of the detector's time.
inline Lanes squaredDistances(const Trajectory& xyz, Eigen::Index i, const std::array<Lanes, 3>& estimate)
{
  std::array<Lanes, 3> d;
  for (Eigen::Index c = 0; c < 3; ++c)
    d[static_cast<std::size_t>(c)] = loadLanes(xyz.col(c).data() + i) - estimate[static_cast<std::size_t>(c)];
  return d[0] * d[0] + (d[1] * d[1] + d[2] * d[2]);
}

// r[k] = sqrt(r[k]) / divisor[k] for k in [from, to) (divisor null: 1), in independent lanes,
// so the roots overlap. The same correctly rounded operations as one sample at a time.
inline void rootsOf(double* r, const double* divisor, Eigen::Index from, Eigen::Index to)
{
  Eigen::Index k = from;
  for (; k + kLanes <= to; k += kLanes) {
    const Lanes root = squareRoot(loadLanes(r + k));
    storeLanes(r + k, divisor ? root / loadLanes(divisor + k) : root);
  }
  for (; k < to; ++k)
    r[k] = divisor ? std::sqrt(r[k]) / divisor[k] : std::sqrt(r[k]);
}

inline Lanes middle(const Lanes& a, const Lanes& b)
{
  return 0.5 * (a + b);
}

} // namespace
} // namespace mocap
