// The robust spike detector on one run: stage 1 marks suspects, stage 2 judges each sample
// without them, the noise scale says how far is too far, and a flag needs both sides' trajectories
// to miss the sample (spike_detection.h, Robust).

#include "spike_detector_parts.h"

namespace mocap::spikes {

namespace {

// Whether the trajectory on each side of sample i, extrapolated to it, misses it by more than
// `limit` (as stage 2 measures: suspects left out, over the prediction's deviation). A spike leaves
// its trajectory and comes back, so both sides miss it; where the motion itself turns sharply (a
// corner, a step, an acceleration out of rest, which a centred quadratic cannot follow and a
// noiseless or smoothed trajectory leaves no noise to hide) one side leads to the sample. A side
// with fewer than kSideSpan samples in the run cannot say, and does not clear the sample.
bool missedFromBothSides(const Trajectory& xyz, const Run& run, Eigen::Index i, double limit, const RobustWork& work)
{
  if (i - kSideSpan >= run.first && predictionResidual(xyz, run, i, Run{i - kSideSpan, i}, work) <= limit)
    return false;
  return !(i + kSideSpan <= run.last && predictionResidual(xyz, run, i, Run{i, i + kSideSpan}, work) <= limit);
}

} // namespace

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
  motionFloor(xyz, run, work);
  for (Eigen::Index i = 0; i < n; ++i)
    work.suspect[static_cast<std::size_t>(i)] =
        work.lineResidual(i) > kSuspectThreshold * work.sigma(i) ? 1 : 0;
  quadraticResiduals(xyz, run, work);
  localSigma(work.fitResidual, floor, work.sigma);
  motionFloor(xyz, run, work);
  runEndSigma(xyz, run, work);
  for (Eigen::Index i = 0; i < n; ++i) {
    // Step 4: within the noise of one side's trajectory, the sample is no spike.
    if (work.fitResidual(i) > threshold * work.sigma(i) &&
        missedFromBothSides(xyz, run, run.first + i, kSideThresholdShare * threshold * work.sigma(i), work))
      flags.push_back(run.first + i);
  }
}

} // namespace mocap::spikes
