// The paper's spike test (Zhang et al., section 4.1.2, eqs 8-9; spike_detection.h, Paper).

#include "spike_detector_parts.h"

namespace mocap::spikes {

void detectPaper(const Trajectory& xyz, const Run& run, double factor, std::vector<Eigen::Index>& flags)
{
  if (run.size() < 3)
    return;
  const Eigen::Index n = run.size() - 1;  // segments
  Eigen::VectorXd segment(n);
  for (Eigen::Index s = 0; s < n; ++s)
    segment(s) = (xyz.row(run.first + s + 1) - xyz.row(run.first + s)).norm();
  const double k = segment.sum() / static_cast<double>(n);  // eq 8
  if (!(k > 0.0))
    return;  // a still marker: no segment can stand out
  const double limit = factor * k;
  for (Eigen::Index i = 1; i < n; ++i)
    if (segment(i - 1) >= limit && segment(i) >= limit)  // eq 9
      flags.push_back(run.first + i);
}

} // namespace mocap::spikes
