#pragma once
// Median selection networks for the robust spike detector, templates over the value type: one
// double, or a vector of lanes (one window per lane) that brings its own order() and middle(),
// found by argument-dependent lookup. Each lane goes through the very operations of the scalar
// code, so every lane width gives the scalar results bit for bit.
//
// Everything here has internal linkage (an unnamed namespace): the AVX2 kernels' unit, compiled
// with -mavx2, includes it too, and its instantiations must never stand in for the baseline
// unit's at link time.

namespace mocap {
namespace {

// Compare-exchange without a branch (minsd/maxsd): sorting networks do not stall on mispredictions.
// std::min and std::max spelled out (their very expressions), so that no function template of
// the standard library is instantiated here.
inline void order(double& a, double& b)
{
  const double low = (b < a) ? b : a;
  b = (a < b) ? b : a;
  a = low;
}

inline double middle(double a, double b)
{
  return 0.5 * (a + b);
}

// Medians of 6 and 7 values through optimal sorting networks (12 and 16 compare-exchanges).
template <typename T>
T median6(T* v)
{
  order(v[0], v[5]), order(v[1], v[3]), order(v[2], v[4]);
  order(v[1], v[2]), order(v[3], v[4]);
  order(v[0], v[3]), order(v[2], v[5]);
  order(v[0], v[1]), order(v[2], v[3]), order(v[4], v[5]);
  order(v[1], v[2]), order(v[3], v[4]);
  return middle(v[2], v[3]);
}

template <typename T>
T median7(T* v)
{
  order(v[0], v[6]), order(v[2], v[3]), order(v[4], v[5]);
  order(v[0], v[2]), order(v[1], v[4]), order(v[3], v[6]);
  order(v[0], v[1]), order(v[2], v[5]), order(v[3], v[4]);
  order(v[1], v[2]), order(v[4], v[6]);
  order(v[2], v[3]), order(v[4], v[5]);
  order(v[1], v[2]), order(v[3], v[4]), order(v[5], v[6]);
  return v[3];
}

// Median of 11 values: the comparators of Batcher's odd-even merge sort (16 inputs) that reach
// the middle output, 32 compare-exchanges.
template <typename T>
T median11(T* v)
{
  order(v[0], v[1]), order(v[2], v[3]), order(v[4], v[5]), order(v[6], v[7]), order(v[8], v[9]);
  order(v[0], v[2]), order(v[1], v[3]), order(v[4], v[6]), order(v[5], v[7]), order(v[8], v[10]);
  order(v[1], v[2]), order(v[5], v[6]), order(v[9], v[10]);
  order(v[0], v[4]), order(v[1], v[5]), order(v[2], v[6]), order(v[3], v[7]);
  order(v[2], v[4]), order(v[3], v[5]);
  order(v[1], v[2]), order(v[3], v[4]), order(v[5], v[6]), order(v[9], v[10]);
  order(v[0], v[8]), order(v[1], v[9]), order(v[2], v[10]);
  order(v[4], v[8]), order(v[5], v[9]), order(v[6], v[10]);
  order(v[3], v[5]), order(v[6], v[8]);
  order(v[5], v[6]);
  return v[5];
}

// The 5th and 6th smallest of 10 values (left in v[4], v[5]; the rest reordered): Waksman's
// 29-comparator sorting network less the 3 comparators that cannot change those two.
template <typename T>
void middlePairOf10(T* v)
{
  order(v[2], v[7]), order(v[1], v[6]), order(v[0], v[5]);
  order(v[1], v[4]), order(v[6], v[9]), order(v[5], v[8]);
  order(v[0], v[2]), order(v[3], v[6]), order(v[7], v[9]);
  order(v[0], v[1]), order(v[2], v[4]), order(v[5], v[7]), order(v[8], v[9]);
  order(v[1], v[2]), order(v[4], v[6]), order(v[7], v[8]), order(v[3], v[5]);
  order(v[2], v[5]), order(v[6], v[8]), order(v[1], v[3]), order(v[4], v[7]);
  order(v[2], v[3]), order(v[6], v[7]);
  order(v[3], v[4]), order(v[5], v[6]);
  order(v[4], v[5]);
}

// The median of 11 values given the middle pair (s₄ ≤ s₅) of 10 of them and the 11th, x:
// max(s₄, min(x, s₅)), one of the values, so the median11 network's answer.
template <typename T>
T medianWithMiddlePair(T low, T high, T x)
{
  order(x, high);  // x = min(x, s₅)
  order(low, x);   // x = max(s₄, x)
  return x;
}

} // namespace
} // namespace mocap
