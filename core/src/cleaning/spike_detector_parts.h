#pragma once
// The spike detector's shared pieces (spike_detection.h), private to core/src/cleaning: the valid
// run a detector judges, the robust detector's windows and cut-offs, and its stages, each in a
// file of its own (spike_paper_detector, spike_median_line, spike_quadratic_prediction,
// spike_noise_scale, spike_robust_detector, spike_replacement).

#include "mocap/cleaning/spike_detection.h"

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace mocap::spikes {

using Trajectory = Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>;

struct Run
{
  Eigen::Index first = 0;
  Eigen::Index last = 0;  // inclusive
  [[nodiscard]] Eigen::Index size() const { return last - first + 1; }
};

// Median of [begin, end) of a sorted range; the mean of the two middle values for an even count.
inline double sortedMedian(const double* begin, const double* end)
{
  const auto n = end - begin;
  return n % 2 == 1 ? begin[n / 2] : 0.5 * (begin[n / 2 - 1] + begin[n / 2]);
}

// Median of a few values (reorders them): insertion sort beats selection below ~16 values.
inline double smallMedian(double* begin, double* end)
{
  for (double* a = begin + 1; a < end; ++a) {
    const double value = *a;
    double* b = a;
    for (; b > begin && *(b - 1) > value; --b)
      *b = *(b - 1);
    *b = value;
  }
  return sortedMedian(begin, end);
}

// The window of `width` samples around `i` inside `run`, shifted inward at the run's ends so it
// keeps its width (a sample at a run end is judged by extrapolation from one side).
inline Run windowAround(const Run& run, Eigen::Index i, Eigen::Index halfWidth)
{
  const Eigen::Index width = 2 * halfWidth + 1;
  if (run.size() <= width)
    return run;
  const Eigen::Index first = std::clamp(i - halfWidth, run.first, run.last - width + 1);
  return {first, first + width - 1};
}

// The robust detector's fixed windows and cut-offs, chosen on the three real takes named in the
// header: a wider fit window follows fast facial motion worse, a narrower one keeps too few
// samples once a block of 3 is left out.
inline constexpr Eigen::Index kLineHalfWidth = 3;       // stage 1: 7 samples; a block of 3 cannot move a median
inline constexpr Eigen::Index kQuadraticHalfWidth = 4;  // stage 2: 9 samples
inline constexpr Eigen::Index kScaleHalfWidth = 5;      // robust scale: median over 11 samples
inline constexpr double kSuspectThreshold = 3.0;        // stage 1 cut-off, in robust standard deviations
inline constexpr std::size_t kMaxLeftOut = 4;           // suspects left out of one stage-2 fit
inline constexpr double kRunEndScaleWeight = 0.5;       // see runEndSigma
inline constexpr double kMotionFloorShare = 0.03;       // see motionFloor
inline constexpr double kRunEndMotionFloorShare = 0.04; // see motionFloor
inline constexpr Eigen::Index kMinRobustRun = 5;        // shorter runs have too few samples to judge one
// Stage 2's window: 9 samples.
inline constexpr int kWindow = 2 * kQuadraticHalfWidth + 1;
// Step 4: each side's extrapolation uses the 8 samples before (after) the judged one, stage 2's
// window shifted to one side.
inline constexpr Eigen::Index kSideSpan = kWindow - 1;
// Step 4: a side leads to the sample when its extrapolation misses by at most this share of the
// threshold (in robust standard deviations): within the noise, not merely under the flag's bar, so
// a small spike in noise is not cleared by a side that misses it by less than the threshold.
inline constexpr double kSideThresholdShare = 0.5;

// Buffers reused across the runs of a trajectory.
struct RobustWork
{
  Eigen::VectorXd lineResidual;
  Eigen::VectorXd fitResidual;
  // The local scale; while stage 2 runs (stage 1's scale is used up by then), the deviations of
  // the interior's predictions until fitResidual is rooted: a buffer of its own cost a fresh
  // allocation, and the page faults of its memory, per marker.
  Eigen::VectorXd sigma;
  std::vector<char> suspect;
};

// Eqs 8-9 on one run P_0..P_n: appends the flagged frames. O(run length).
void detectPaper(const Trajectory& xyz, const Run& run, double factor, std::vector<Eigen::Index>& flags);

// The robust detector on one run (spike_detection.h, steps 1-3): appends the flagged frames.
// O(run length).
void detectRobust(const Trajectory& xyz, const Run& run, double threshold, double floor, RobustWork& work,
                  std::vector<Eigen::Index>& flags);

// Stage 1: each sample's distance from a local line fitted by medians over 7 samples, r(i − run.first).
// O(run length).
void medianLineResiduals(const Trajectory& xyz, const Run& run, Eigen::VectorXd& r);

// Stage 2: each sample's distance from its prediction without itself and the worst suspects,
// relative to the prediction's deviation, into work.fitResidual (work.suspect and
// work.lineResidual set by stage 1). O(run length).
void quadraticResiduals(const Trajectory& xyz, const Run& run, RobustWork& work);

// Stage 2 for sample `i` predicted from window `w`. O(window).
[[nodiscard]] double predictionResidual(const Trajectory& xyz, const Run& run, Eigen::Index i, const Run& w,
                                        const RobustWork& work);

// The robust scale: the local median of `r` over 11 samples per 3-D unit normal, at least `floor`.
// O(r.size()).
void localSigma(const Eigen::VectorXd& r, double floor, Eigen::VectorXd& sigma);

// The scale floor of a moving marker: a share of its speed per frame over stage 2's window,
// kMotionFloorShare, or kRunEndMotionFloorShare within 4 samples of a run end (raises work.sigma).
// O(run length).
void motionFloor(const Trajectory& xyz, const Run& run, RobustWork& work);

// The scale floor of the samples within 4 of a run end, from their inward neighbours'
// lopsided predictions (raises work.sigma there). O(1) per run end.
void runEndSigma(const Trajectory& xyz, const Run& run, RobustWork& work);

// The replacements of replaceSpikes for one trajectory: `flagged` holds valid frames, ascending
// and unique; appends the replaced frames and their positions. O(#flags · log #flags).
void replaceFlagged(const Trajectory& xyz, const Eigen::Ref<const ValidMask>& valid,
                    const std::vector<Eigen::Index>& flagged, std::vector<Eigen::Index>& frames,
                    std::vector<Eigen::RowVector3d>& positions);

} // namespace mocap::spikes
