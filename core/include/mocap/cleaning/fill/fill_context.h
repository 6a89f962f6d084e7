#pragma once

#include "mocap/model/take.h"

#include <vector>

namespace mocap {

/// What the regression-based fills of one take share across its gaps, computed once: a
/// frame-major copy of every stride-th frame (the "grid", at most `maxRows` rows), so ranking and
/// training read contiguous memory instead of one cache line per coordinate, and each marker's
/// usual large step, to tell a jump (label swap, glitch) from motion. The take must outlive it
/// and stay unchanged.
class FillContext
{
public:
  /// O(#frames · #markers). Throws InvalidArgument when maxRows < 1. Not a paper equation (a
  /// cache for regression_fill.h and auto_fill.h).
  explicit FillContext(const Take& take, Eigen::Index maxRows = 1000);

  [[nodiscard]] const Take& take() const { return *m_take; }
  /// Frames between grid rows; grid row r is frame r · stride().
  [[nodiscard]] Eigen::Index stride() const { return m_stride; }
  [[nodiscard]] Eigen::Index rows() const { return m_valid.rows(); }
  /// The 3 · #markers coordinates of grid row r (x, y, z of marker 0, then marker 1, ...).
  [[nodiscard]] const double* row(Eigen::Index r) const
  {
    return m_positions.data() + r * m_positions.cols();
  }
  [[nodiscard]] bool valid(Eigen::Index r, Eigen::Index marker) const { return m_valid(r, marker); }
  /// The 95th percentile of the marker's squared frame-to-frame steps, sampled at the grid
  /// frames (0 when fewer than 10 are known).
  [[nodiscard]] double usualSquaredStep(Eigen::Index marker) const
  {
    return m_usualSquaredStep[static_cast<std::size_t>(marker)];
  }

private:
  const Take* m_take;
  Eigen::Index m_stride = 1;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> m_positions;
  Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> m_valid;
  std::vector<double> m_usualSquaredStep;
};

} // namespace mocap
