#include "spike_kernels_avx2.h"

#include "median_networks.h"

#include <immintrin.h>

namespace mocap {

namespace {

// Four windows, one per lane. min/max take their operands in the order of the SSE2 code (b
// first), which gives the same answer for equal values and signed zeros.
struct Lanes4
{
  __m256d v;
};

void order(Lanes4& a, Lanes4& b)
{
  const __m256d low = _mm256_min_pd(b.v, a.v);
  b.v = _mm256_max_pd(b.v, a.v);
  a.v = low;
}

Lanes4 middle(const Lanes4& a, const Lanes4& b)
{
  return {_mm256_mul_pd(_mm256_set1_pd(0.5), _mm256_add_pd(a.v, b.v))};
}

Lanes4 load(const double* p)
{
  return {_mm256_loadu_pd(p)};
}

constexpr std::ptrdiff_t kLineHalfWidth = 3;  // spike_detector_parts.h's: a 7-sample window

} // namespace

std::ptrdiff_t avx2::squaredLineResiduals(const double* x, const double* y, const double* z, std::ptrdiff_t from,
                                          std::ptrdiff_t to, double* out)
{
  const double* const axes[3] = {x, y, z};
  std::ptrdiff_t k = from;
  for (; k + 3 < to; k += 4) {
    __m256d square[3];
#pragma GCC unroll 3
    for (int c = 0; c < 3; ++c) {
      const double* w = axes[c] + (k - kLineHalfWidth);  // w[l + j]: sample j of lane l's window
      Lanes4 values[2 * kLineHalfWidth + 1];
#pragma GCC unroll 8
      for (int j = 0; j < 2 * kLineHalfWidth; ++j)
        values[j] = {_mm256_sub_pd(load(w + j + 1).v, load(w + j).v)};
      const Lanes4 slope = median6(values);
#pragma GCC unroll 8
      for (int j = 0; j <= 2 * kLineHalfWidth; ++j)
        values[j] = {_mm256_sub_pd(load(w + j).v, _mm256_mul_pd(slope.v, _mm256_set1_pd(double(j - kLineHalfWidth))))};
      const Lanes4 level = median7(values);
      const __m256d d = _mm256_sub_pd(load(axes[c] + k).v, level.v);
      square[c] = _mm256_mul_pd(d, d);
    }
    // Summed as Eigen's norm() sums a 3-vector: x² + (y² + z²).
    _mm256_storeu_pd(out + k, _mm256_add_pd(square[0], _mm256_add_pd(square[1], square[2])));
  }
  return k;
}

} // namespace mocap
