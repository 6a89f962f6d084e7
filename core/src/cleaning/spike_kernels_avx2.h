#pragma once
// Kernels of the robust spike detector on four lanes (AVX2), in a unit of their own that is
// compiled with -mavx2 and called only when the CPU has AVX2 (spike_median_line.cpp checks at run
// time). Raw pointers only: nothing with external linkage but these functions is compiled for
// AVX2, so no AVX2 code can stand in for a baseline function at link time.
//
// Each gives, lane by lane, the very operations of the two-lane (SSE2) code of
// spike_lanes.h and spike_median_line.cpp, so the detector's results do not depend on which path ran.

#include <cstddef>

namespace mocap::avx2 {

/// Stage 1 (the median line, medianLineResidualsAt) for samples k = from, from + 4, … while
/// k + 3 < to, four at a time: out[k] = the squared distance of sample k from its 7-sample median
/// line, the axes' samples at x[k], y[k], z[k]. Every window x[k − 3 .. k + 3] must be inside the
/// run. Returns the first sample not done. O(to − from).
[[nodiscard]] std::ptrdiff_t squaredLineResiduals(const double* x, const double* y, const double* z,
                                                  std::ptrdiff_t from, std::ptrdiff_t to, double* out);

} // namespace mocap::avx2
