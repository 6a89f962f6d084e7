// The robust spike detector on one run: stage 1 marks suspects, stage 2 judges each sample
// without them, the noise scale says how far is too far (spike_detection.h, Robust).

#include "spike_detector_parts.h"

namespace mocap::spikes {

void detectRobust(const Trajectory& xyz, const Run& run, double threshold, double floor, RobustWork& work,
                  std::vector<Eigen::Index>& flags)
{
  const Eigen::Index n = run.size();
  if (n < kMinRobustRun)
    return;
  work.lineResidual.resize(n);
  work.fitResidual.resize(n);
  work.suspect.assign(static_cast<std::size_t>(n), 0);
  medianLineResiduals(xyz, run, work.lineResidual);
  localSigma(work.lineResidual, floor, work.sigma);
  for (Eigen::Index i = 0; i < n; ++i)
    work.suspect[static_cast<std::size_t>(i)] =
        work.lineResidual(i) > kSuspectThreshold * work.sigma(i) ? 1 : 0;
  quadraticResiduals(xyz, run, work);
  localSigma(work.fitResidual, floor, work.sigma);
  runEndSigma(xyz, run, work);
  for (Eigen::Index i = 0; i < n; ++i)
    if (work.fitResidual(i) > threshold * work.sigma(i))
      flags.push_back(run.first + i);
}

} // namespace mocap::spikes
