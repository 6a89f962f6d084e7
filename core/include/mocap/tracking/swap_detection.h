#pragma once

#include "mocap/model/marker_edits.h"  // exchangeMarkersFrom, the repair of one swap
#include "mocap/model/take.h"
#include "mocap/base/job_control.h"

#include <vector>

namespace mocap {

struct SwapOptions
{
  /// A marker "jumps" in a frame when its distance from the constant-velocity prediction
  /// (2pₜ₋₁ − pₜ₋₂) exceeds jumpFactor × its 95th-percentile prediction error over the take, and
  /// at least minJump (in the take's units; 0 = 1 mm) ; jumpFactor in [2, 1000].
  double jumpFactor = 10.0;
  double minJump = 0.0;
  /// A swap explains the jumps when, with the two markers exchanged, the larger of the two
  /// prediction errors is below swappedFraction × the smaller jump without the exchange; (0, 1).
  double swappedFraction = 0.35;
};

/// Per marker, the prediction error above which a step is a jump (see SwapOptions::jumpFactor).
/// Throws InvalidArgument for options out of range. O(#frames · #markers).
[[nodiscard]] Eigen::VectorXd jumpThresholds(const Take& take, const SwapOptions& options = {});

/// #frames × #markers: the samples whose constant-velocity prediction error is a jump (a swap, a
/// mislabelled stretch or a glitch); false throughout for model outputs (isMarker), which are no
/// positions. O(#frames · #markers).
[[nodiscard]] SampleMask findJumps(const Take& take, const SwapOptions& options = {});

/// Two labels exchanging their trajectories from `frame` on (until the next swap of the pair).
struct LabelSwap
{
  Eigen::Index frame = 0;  ///< 0-based, the first frame with the exchanged samples
  Eigen::Index first = 0;  ///< marker indices, first < second
  Eigen::Index second = 0;
  double jump = 0.0;       ///< sum of both markers' prediction errors as captured
  double explained = 0.0;  ///< the same with the markers exchanged
};

/// Finds frames where two labels exchange (paper §2 tracking errors: two markers crossing):
/// frame by frame, markers whose prediction error is a jump are paired when exchanging their
/// samples explains both jumps (best explained pairs first); each found swap is undone at once by
/// exchanging every later sample of the two markers (positions, validity, residuals, camera
/// masks, states), so the swap back, where the labels return, is found as the next swap of the
/// pair and undone in turn. Works on and repairs `take` in place; returns the swaps in frame
/// order for review. Needs the three samples t−2..t of both markers valid; model outputs are never
/// swapped. Not a paper equation.
/// Throws InvalidArgument for options out of range. O(#frames · #markers + #swaps · #frames).
std::vector<LabelSwap> repairSwaps(Take& take, const SwapOptions& options = {}, const JobControl& job = {});

/// repairSwaps on a copy: the swaps without changing `take`.
[[nodiscard]] std::vector<LabelSwap> detectSwaps(const Take& take, const SwapOptions& options = {},
                                                const JobControl& job = {});

} // namespace mocap
