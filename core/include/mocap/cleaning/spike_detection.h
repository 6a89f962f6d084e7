#pragma once

#include "mocap/model/sample_patch.h"
#include "mocap/base/job_control.h"
#include "mocap/model/take.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// Impulsive noise ("spikes", the paper's "bad points", section 4.1): samples far off their
/// trajectory. Detection and replacement are separate steps, so a view can show the flags first.
///
/// - `Paper`: section 4.1.2 as written. Per valid run P_0..P_n, k = Σ|P_{i-1}P_i| / n (eq 8), and
///   P_i (0 < i < n) is bad when |P_{i-1}P_i| ≥ factor·k and |P_iP_{i+1}| ≥ factor·k (eq 9, factor
///   1.5). It cannot see a run's first or last sample, nor two bad samples in a row (the segment
///   between them is short), and wherever a marker moves faster than 1.5 times its average every
///   segment is long, so clean samples are flagged: 16-19 % of the samples of the clean takes below.
/// - `Robust`: a Hampel test on the residual from a local robust fit, in three steps per run:
///   1. a line fitted by medians over 7 samples (slope: median of first differences; level:
///      median of the detrended samples) marks suspects, samples more than 3 robust standard
///      deviations off it; a block of up to 3 bad samples cannot move the medians;
///   2. each sample is predicted by a tricube-weighted quadratic over 9 samples without itself and
///      without the (up to 4) worst suspects of the window, and the distance to the prediction is
///      divided by its standard deviation relative to the noise, sqrt(1 + var(prediction));
///   3. a sample is flagged when that residual exceeds `threshold` robust standard deviations: the
///      median residual over the 11 surrounding samples / 1.5382 (the median length of a 3-D
///      standard normal vector), at least `noiseFloor` and at least 3 % of the distance the marker
///      moves per frame over the 9 samples (4 % within 4 samples of a run end, where the quadratic
///      extrapolates: it follows a fast marker only to within a share of that, and smooth motion is
///      no spike); within 4 samples of a run end, also at least half the scale of the same lopsided
///      prediction made for the inward neighbours;
///   4. a flagged sample is kept only when the trajectory on each side misses it too: stage 2's
///      quadratic over the 8 samples before it, and over the 8 after it (suspects left out),
///      extrapolated to the sample, each miss by more than half the threshold (in the same robust
///      standard deviations). A spike leaves its trajectory and comes back; where the motion turns
///      sharply (a corner, a foot strike, a start out of rest, both edges of a step or a swap) one
///      side leads to the sample, and a noiseless or smoothed trajectory (a solver's skeleton, a
///      filtered 6DOF body) has no noise to hide the centred fit's miss there. Within 8 samples of
///      a run end only the side with 8 samples can clear a flag.
///   Windows shift inward at run ends, so the first and last samples of a run are judged by
///   extrapolation from one side.
///
/// Measured with evaluateSpikes (5 mm spikes, seeds 1-10 × 200 spikes, defaults; `mocap eval-spikes`):
///
/// | take (rate)              | Robust recall | Robust false alarms | Paper recall | Paper false alarms |
/// |--------------------------|---------------|---------------------|--------------|--------------------|
/// | NoseMoCap.trc (60 Hz)    | 99.87 %       | 0.0008 %            | 27.3 %       | 0.006 %            |
/// | CheeksMoCap.trc (60 Hz)  | 99.97 %       | 0.0002 %            | 30.0 %       | 0.002 %            |
/// | Facial-Sing.c3d (100 Hz) | 99.34 %       | 0.0005 %            | 33.1 %       | 0.006 %            |
///
/// Step 4 costs some recall (without it: 99.93 %, 99.97 %, 99.63 %; with 2 mm spikes 98.7 %,
/// 99.8 %, 92.5 % instead of 99.5 %, 99.9 %, 95.1 %) and halves the flags on uncorrupted takes:
/// Robust flags 16, 2 and 198 samples of these three (35, 2 and 415 without it: fast mouth and
/// brow moves of a few mm in one or two frames, glitches and the edges of swaps in Facial-Sing),
/// and on other labs' smooth takes ART's filtered 6DOF body 258 of 42 994 (631 without) and an
/// OptiTrack solver's skeleton 169 of 41 436 (808). The scale's share of the speed (step 3) then
/// took Facial-Sing to 163 flags (5 mm recall 99.40 % → 99.34 %, 2 mm 92.5 % → 92.0 %; the other
/// two takes unchanged), ART's body to 118 and the skeleton to 160, and a synthetic smooth take
/// (sines with 0.01 mm noise, 30-240 Hz) from up to 12 flags to none. Without step 4, 12 of the 15 misses in 9 000
/// spiked samples were next to a gap (half in valid runs shorter than 5 samples, which Robust does
/// not judge); the misses step 4 adds have not been sorted.
enum class SpikeMethod
{
  Paper,
  Robust,
};

/// "paper" or "robust" (exactly, lower case); nullopt otherwise. O(1).
[[nodiscard]] std::optional<SpikeMethod> parseSpikeMethod(std::string_view name);
/// The name parseSpikeMethod reads back. O(1).
[[nodiscard]] std::string_view spikeMethodName(SpikeMethod method);
/// Every value's name, "a|b|c" (for usage texts and errors). O(#values).
[[nodiscard]] std::string spikeMethodNames();

struct SpikeOptions
{
  SpikeMethod method = SpikeMethod::Robust;
  /// Paper: eq 9's multiple of k. Finite and > 0.
  double factor = 1.5;
  /// Robust: flag a sample whose distance from the local robust fit (made without it and without
  /// other suspects) exceeds this many robust standard deviations of that distance (step 3 above).
  /// Finite and > 0. Lower finds smaller spikes and flags more fast, clean motion.
  double threshold = 6.0;
  /// Robust: the smallest robust standard deviation, in millimetres, of a marker at rest, so a
  /// noiseless or quantised trajectory does not turn rounding into spikes (with the default
  /// threshold, nothing under 0.3 mm off the fit is flagged); a moving marker's is also at least
  /// 3 % of its speed per frame (4 % at run ends; step 3). Finite and ≥ 0.
  double noiseFloor = 0.05;
  /// Robust: a glitch longer than the robust windows can take is found a part at a time (its
  /// worst samples first), and a spike can hide a smaller one beside it; both stand out once the
  /// flags are replaced. With more than 1, the trajectory is judged again with the flags so far
  /// replaced as replaceSpikes does, until a pass adds no flag or after this many passes.
  /// Measured on Facial-Sing.c3d (detect, repair, detect again): 1 pass 198 then 20 flags; 8 and
  /// 100 passes 213 then 4.
  /// The default keeps the single pass the evaluations above measured. Paper always makes one
  /// pass (eq 9 as written). In 1..100.
  int maxPasses = 1;
};

/// Throws InvalidArgument naming the first option out of its documented range. O(1).
void checkSpikeOptions(const SpikeOptions& options);

/// A flagged sample: marker index and 0-based frame index.
struct SpikeFlag
{
  Eigen::Index marker = 0;
  Eigen::Index frame = 0;

  friend bool operator==(const SpikeFlag& a, const SpikeFlag& b)
  {
    return a.marker == b.marker && a.frame == b.frame;
  }
};

/// Flagged frames (ascending) of one trajectory `xyz` (#frames × 3, `valid` #frames). Each valid
/// run is judged on its own, never across a gap; invalid samples are never read or flagged.
/// `options.noiseFloor` is taken in the units of `xyz`. Runs too short to judge (fewer than 3
/// samples for Paper, fewer than 5 for Robust) and, for Paper, runs that do not move (k = 0) give
/// no flags. Paper: eqs 8-9, O(#frames). Robust: O(#frames · passes) (fixed windows of 7, 9 and 11
/// samples; a further pass only while the last one added flags, at most maxPasses).
/// Throws InvalidArgument when the sizes disagree, an option is out of range or a valid sample
/// is not finite (naming its frame).
[[nodiscard]] std::vector<Eigen::Index>
detectSpikes(const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>& xyz,
             const Eigen::Ref<const ValidMask>& valid, const SpikeOptions& options);

/// Every flagged sample of every marker point (model outputs are never flagged: marker_points.h),
/// markers then frames ascending; `noiseFloor` is converted
/// from millimetres to the take's units, so the flags do not depend on the units. An empty take
/// gives no flags. O(#frames · #markers). Throws InvalidArgument as above, naming the marker.
[[nodiscard]] std::vector<SpikeFlag> detectSpikes(const Take& take, const SpikeOptions& options,
                                                 const JobControl& job = {});

/// Replacements for the flagged samples (eq 10 and its extension to blocks), one patch per marker
/// with flags, markers ascending; each replaced sample is valid with residual 0 and origin
/// SampleOrigin::Edited (earlier operations cleared), and nothing else changes. Within a valid run, a block of consecutive
/// flagged samples is interpolated linearly between the nearest unflagged valid samples on both
/// sides, so a single one becomes the mid-value of its neighbours (eq 10). A block at a run end (no
/// unflagged neighbour on one side) is extrapolated along the least-squares line through the
/// nearest (up to 4) unflagged samples of the run on the other side, or set to that neighbour when
/// it is the only one. A block that is a whole run has nothing to be rebuilt from and is left as it
/// is (in no patch). Flags on invalid samples are ignored (filling gaps is another step's job);
/// repeated flags count once. O(#flags · log #flags).
/// Throws InvalidArgument when a flag's marker or frame lies outside the take.
[[nodiscard]] std::vector<SamplePatch> replaceSpikes(const Take& take, const std::vector<SpikeFlag>& flags);

} // namespace mocap
