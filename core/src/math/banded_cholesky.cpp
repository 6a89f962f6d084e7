#include "mocap/math/banded_cholesky.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace mocap {

namespace {

// Substitution with a compile-time bandwidth B and K right-hand sides: the last B solved rows stay
// in registers, so each row waits on one multiply-add of the previous row instead of on a store
// and reload. The loops over the window are unrolled (every index a constant, which is what lets
// the compiler keep it in registers), and only the B rows at the start of each sweep test whether
// a band entry reaches outside the matrix.
template <int B, int K>
void substitute(const double* factor, Eigen::Index n, double* x)
{
  constexpr Eigen::Index stride = B + 1;
  constexpr auto b = static_cast<std::size_t>(B), k = static_cast<std::size_t>(K);
  double window[b][k] = {};  // window[d − 1]: the row d rows back along the sweep
  const auto shiftIn = [&window](const double (&row)[k]) {
#pragma GCC unroll 8
    for (std::size_t d = b - 1; d > 0; --d)
#pragma GCC unroll 8
      for (std::size_t c = 0; c < k; ++c)
        window[d][c] = window[d - 1][c];
#pragma GCC unroll 8
    for (std::size_t c = 0; c < k; ++c)
      window[0][c] = row[c];
  };
  // row[c] −= Σ_d band(d) · window[d − 1][c], d from B down to 1, skipping the d where `reaches`
  // is false (band entries outside the matrix).
  const auto subtractWindow = [&window](double (&row)[k], auto band, auto reaches) {
#pragma GCC unroll 8
    for (Eigen::Index d = B; d >= 1; --d) {
      if (!reaches(d))
        continue;
      const double l = band(d);
      const auto& back = window[static_cast<std::size_t>(d - 1)];
#pragma GCC unroll 8
      for (std::size_t c = 0; c < k; ++c)
        row[c] -= l * back[c];
    }
  };
  const auto load = [x](Eigen::Index i, double (&row)[k]) {
#pragma GCC unroll 8
    for (std::size_t c = 0; c < k; ++c)
      row[c] = x[i * K + static_cast<Eigen::Index>(c)];
  };
  const auto store = [x](Eigen::Index i, const double (&row)[k], double scale) {
#pragma GCC unroll 8
    for (std::size_t c = 0; c < k; ++c)
      x[i * K + static_cast<Eigen::Index>(c)] = row[c] * scale;
  };
  const Eigen::Index edge = std::min<Eigen::Index>(B, n);
  // Forward, L z = r, then z / D written back (the window keeps z for the following rows).
  const auto forward = [&](Eigen::Index i, auto reaches) {
    double z[k];
    load(i, z);
    subtractWindow(z, [&](Eigen::Index d) { return factor[i * stride + d]; }, reaches);
    shiftIn(z);
    store(i, z, 1.0 / factor[i * stride]);
  };
  for (Eigen::Index i = 0; i < edge; ++i)
    forward(i, [i](Eigen::Index d) { return d <= i; });
  for (Eigen::Index i = edge; i < n; ++i)
    forward(i, [](Eigen::Index) { return true; });
  // Backward, Lᵀ x = z / D.
  for (auto& row : window)
    for (double& value : row)
      value = 0.0;
  const auto backward = [&](Eigen::Index i, auto reaches) {
    double v[k];
    load(i, v);
    subtractWindow(v, [&](Eigen::Index d) { return factor[(i + d) * stride + d]; }, reaches);
    shiftIn(v);
    store(i, v, 1.0);
  };
  for (Eigen::Index i = n - 1; i >= n - edge; --i)
    backward(i, [i, n](Eigen::Index d) { return i + d <= n - 1; });
  for (Eigen::Index i = n - edge - 1; i >= 0; --i)
    backward(i, [](Eigen::Index) { return true; });
}

template <int K>
bool substituteFixed(Eigen::Index b, const double* factor, Eigen::Index n, double* x)
{
  switch (b) {
  case 1: substitute<1, K>(factor, n, x); return true;
  case 2: substitute<2, K>(factor, n, x); return true;
  case 3: substitute<3, K>(factor, n, x); return true;
  case 4: substitute<4, K>(factor, n, x); return true;
  case 5: substitute<5, K>(factor, n, x); return true;
  case 6: substitute<6, K>(factor, n, x); return true;
  case 7: substitute<7, K>(factor, n, x); return true;
  default: return false;
  }
}

} // namespace

BandedCholesky::BandedCholesky(Band lower) : m_factor(std::move(lower))
{
  const Eigen::Index n = m_factor.rows();
  if (m_factor.cols() < 1)
    throw InvalidArgument("banded Cholesky: the band needs at least the diagonal");
  const Eigen::Index b = m_factor.cols() - 1;
  Eigen::VectorXd scaled(b + 1);  // L(i, k) · D(k) for the row being factorised
  Eigen::VectorXd reciprocal(n);  // 1 / D(i): one division per row instead of one per entry
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index kMax = std::min(b, i);
    for (Eigen::Index k = kMax; k >= 1; --k) {
      // A(i, j) with j = i − k, minus the contributions of the columns left of j.
      const Eigen::Index j = i - k;
      double s = m_factor(i, k);
      for (Eigen::Index kk = kMax; kk > k; --kk)
        s -= scaled(kk) * m_factor(j, kk - k);
      m_factor(i, k) = s * reciprocal(j);
      scaled(k) = s;
    }
    double d = m_factor(i, 0);
    for (Eigen::Index k = 1; k <= kMax; ++k)
      d -= scaled(k) * m_factor(i, k);
    // Relative test: a pivot lost to rounding means the matrix is singular for our purposes.
    if (!(d > 1e-13 * std::abs(m_factor(i, 0))) || !std::isfinite(d))
      throw InvalidArgument("banded Cholesky: matrix is not positive definite (pivot " + std::to_string(i) +
                            ")");
    m_factor(i, 0) = d;
    reciprocal(i) = 1.0 / d;
  }
}

void BandedCholesky::solveInPlace(Eigen::Ref<Eigen::MatrixXd> rhs) const
{
  const Eigen::Index n = size();
  if (rhs.rows() != n)
    throw InvalidArgument("banded Cholesky: right-hand side has " + std::to_string(rhs.rows()) +
                          " rows, expected " + std::to_string(n));
  // Substitution is a chain of dependent multiply-adds; solving the columns side by side in a
  // row-major copy lets their chains overlap (3× faster for trajectories' x, y, z).
  Band x = rhs;
  solveInPlace(x);
  rhs = x;
}

void BandedCholesky::solveInPlace(Band& x) const
{
  const Eigen::Index n = size();
  const Eigen::Index b = bandwidth();
  if (x.rows() != n)
    throw InvalidArgument("banded Cholesky: right-hand side has " + std::to_string(x.rows()) +
                          " rows, expected " + std::to_string(n));
  const Eigen::Index k = x.cols();
  double* data = x.data();
  const double* factor = m_factor.data();
  if ((k == 3 && substituteFixed<3>(b, factor, n, data)) ||
      (k == 1 && substituteFixed<1>(b, factor, n, data)))
    return;
  const Eigen::Index stride = b + 1;
  for (Eigen::Index i = 0; i < n; ++i) {
    double* xi = data + i * k;
    const double* li = factor + i * stride;
    const Eigen::Index kMax = std::min(b, i);
    for (Eigen::Index d = 1; d <= kMax; ++d) {
      const double l = li[d];
      const double* xj = xi - d * k;
      for (Eigen::Index c = 0; c < k; ++c)
        xi[c] -= l * xj[c];
    }
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    const double inverse = 1.0 / factor[i * stride];
    for (Eigen::Index c = 0; c < k; ++c)
      data[i * k + c] *= inverse;
  }
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    double* xi = data + i * k;
    const Eigen::Index kMax = std::min(b, n - 1 - i);
    for (Eigen::Index d = 1; d <= kMax; ++d) {
      const double l = factor[(i + d) * stride + d];
      const double* xj = xi + d * k;
      for (Eigen::Index c = 0; c < k; ++c)
        xi[c] -= l * xj[c];
    }
  }
}

BandedCholesky::Band BandedCholesky::inverseBand() const
{
  // With A = L D Lᵀ and S = A⁻¹: S = D⁻¹ L⁻¹ + (I − Lᵀ) S. Read from the bottom row up, the entries
  // S(j, i) for i < j ≤ i + b need only S(k, j) with k, j in (i, i + b], already in the band.
  const Eigen::Index n = size();
  const Eigen::Index b = bandwidth();
  Band inverse = Band::Zero(n, b + 1);
  const auto at = [&inverse](Eigen::Index r, Eigen::Index c) {
    return r >= c ? inverse(r, r - c) : inverse(c, c - r);
  };
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    const Eigen::Index kMax = std::min(b, n - 1 - i);
    for (Eigen::Index dj = kMax; dj >= 1; --dj) {
      const Eigen::Index j = i + dj;
      double s = 0.0;
      for (Eigen::Index dk = 1; dk <= kMax; ++dk)
        s -= m_factor(i + dk, dk) * at(i + dk, j);
      inverse(j, dj) = s;
    }
    double s = 1.0 / m_factor(i, 0);
    for (Eigen::Index dk = 1; dk <= kMax; ++dk)
      s -= m_factor(i + dk, dk) * inverse(i + dk, dk);
    inverse(i, 0) = s;
  }
  return inverse;
}

} // namespace mocap
