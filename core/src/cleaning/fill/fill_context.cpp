#include "mocap/cleaning/fill/fill_context.h"

#include "mocap/base/error.h"

#include <algorithm>

namespace mocap {

FillContext::FillContext(const Take& take, Eigen::Index maxRows) : m_take(&take)
{
  if (maxRows < 1)
    throw InvalidArgument("fill context: at least one grid row is needed");
  const Eigen::Index frames = take.frameCount();
  const Eigen::Index markers = take.markerCount();
  m_stride = std::max<Eigen::Index>(1, (frames + maxRows - 1) / maxRows);
  const Eigen::Index rows = frames > 0 ? (frames - 1) / m_stride + 1 : 0;
  m_positions.resize(rows, 3 * markers);
  m_valid.resize(rows, markers);
  const auto valid = take.valid();
  std::vector<double> steps;
  m_usualSquaredStep.assign(static_cast<std::size_t>(markers), 0.0);
  for (Eigen::Index m = 0; m < markers; ++m) {
    const auto trajectory = take.trajectory(m);
    for (Eigen::Index r = 0; r < rows; ++r) {
      m_positions.block<1, 3>(r, 3 * m) = trajectory.row(r * m_stride);
      m_valid(r, m) = valid(r * m_stride, m);
    }
    // Steps between consecutive valid samples at the grid frames: enough for a percentile.
    steps.clear();
    for (Eigen::Index r = 0; r < rows; ++r) {
      const Eigen::Index f = std::max<Eigen::Index>(1, r * m_stride);
      if (f < frames && valid(f, m) && valid(f - 1, m))
        steps.push_back((trajectory.row(f) - trajectory.row(f - 1)).squaredNorm());
    }
    if (steps.size() < 10)
      continue;
    const auto rank = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() * 95 / 100);
    std::nth_element(steps.begin(), rank, steps.end());
    m_usualSquaredStep[static_cast<std::size_t>(m)] = *rank;
  }
}

} // namespace mocap
