#pragma once

#include "mocap/tracking/swap_detection.h"
#include "mocap/tracking/take_tracking.h"

#include <cstdint>
#include <vector>

namespace mocap {

struct TrackingEvaluationOptions
{
  std::uint64_t seed = 1;  ///< same seed, same take, same options: same numbers
  /// Fragments of the unlabelled copy are uniform in 1..2·meanFragmentLength frames (≥ 1), and
  /// each cut drops 0..maxCutGap frames (0..1000), so the labeller must join across gaps.
  Eigen::Index meanFragmentLength = 150;
  Eigen::Index maxCutGap = 10;
  /// Label swaps injected into the labelled copy, each between a marker and one of its three
  /// nearest neighbours over minSwapLength..maxSwapLength frames where both are valid (0..1000).
  int swaps = 10;
  Eigen::Index minSwapLength = 20;
  Eigen::Index maxSwapLength = 300;
  TrackOptions track;
  SwapOptions swapDetection;
};

/// A take made unlabelled, with which truth samples it still holds.
struct UnlabelledCopy
{
  Take take;          ///< only Unlabeled markers holding the shuffled fragments
  SampleMask kept;    ///< #frames × #take markers: the sample is in the copy (scored)
  Eigen::Index fragments = 0;
};

/// One injected swap: markers `first` and `second` exchanged over frames [begin, end).
struct InjectedSwap
{
  Eigen::Index first = 0;
  Eigen::Index second = 0;
  Eigen::Index begin = 0;
  Eigen::Index end = 0;
};

struct TrackingEvaluation
{
  Eigen::Index markers = 0;     ///< labelled markers scored
  Eigen::Index frames = 0;
  Eigen::Index fragments = 0;   ///< fragments in the unlabelled copy
  Eigen::Index samples = 0;     ///< samples scored (kept in the unlabelled copy)
  Eigen::Index recovered = 0;   ///< of those, back under their true label
  double labelRecovery = 0.0;   ///< recovered / samples (goal ≥ 0.995)
  /// The same over the valid runs of the take that hold no jump (findJumps): where the take's
  /// own labels are trustworthy, not themselves a tracking error.
  Eigen::Index cleanSamples = 0;
  Eigen::Index cleanRecovered = 0;
  double cleanLabelRecovery = 0.0;
  TrackReport track;            ///< what the tracker and labeller did
  int swapsInjected = 0;
  int swapsFound = 0;            ///< injected swaps whose start and end were both found
  int falseAlarms = 0;           ///< found swap boundaries matching no injected one
  int swapsInOriginal = 0;       ///< swaps found in the untouched take (its own tracking errors)
  double swappedAgreement = 0.0;   ///< fraction of samples under their true label with the swaps
  double repairedAgreement = 0.0;  ///< the same after repairSwaps
  std::uint64_t seed = 0;
};

/// The take's labelled markers (not isUnlabelledLabel) cut into fragments at random (see the
/// options), shuffled with the valid runs of the take's own unlabelled markers (strays, not
/// scored) and packed into "Unlabeled" markers (appendFragments). Deterministic in (take, options).
/// Throws InvalidArgument for options out of range. O(#frames · #markers).
[[nodiscard]] UnlabelledCopy makeUnlabelledCopy(const Take& take, const TrackingEvaluationOptions& options = {});

/// A copy of the take with `options.swaps` label swaps injected (fewer when the take leaves no
/// room), listed in `swaps`. Deterministic in (take, options). O(#frames · #markers · swaps).
[[nodiscard]] Take makeSwappedCopy(const Take& take, const TrackingEvaluationOptions& options,
                                   std::vector<InjectedSwap>& swaps);

/// Fraction of the `scored` samples of the truth's markers (#frames × #truth markers; all
/// valid samples when empty) found in `result` under the same label at exactly the same position.
[[nodiscard]] double labelAgreement(const Take& truth, const Take& result, const SampleMask& scored,
                                    Eigen::Index* recovered = nullptr, Eigen::Index* samples = nullptr);

/// #frames × #markers: the valid samples of runs (findValidRuns) that hold no jump (findJumps).
[[nodiscard]] SampleMask trustworthySamples(const Take& take, const SwapOptions& options = {});

/// The issue-8 protocol on a labelled take: (1) make it unlabelled and fragmented
/// (makeUnlabelledCopy), track and label it with the take's own marker set (markerSetFromTake:
/// the neutral frame) and score the fraction of samples back under their true label, over all
/// samples and over trustworthySamples; (2) inject
/// label swaps (makeSwappedCopy), detect and repair them (repairSwaps) and count injected swaps
/// found, false alarms and the agreement before and after repair. Not a paper equation.
/// Throws InvalidArgument for an empty take, fewer than four labelled markers or options out of
/// range. O(tracking + labelling + swap repair).
[[nodiscard]] TrackingEvaluation evaluateTracking(const Take& take, const TrackingEvaluationOptions& options = {});

} // namespace mocap
