#pragma once

#include "mocap/cleaning/spike_detection.h"
#include "mocap/model/take.h"

#include <cstdint>
#include <string>
#include <vector>

namespace mocap {

/// How evaluateSpikes corrupts the take. Spikes come in three shapes, in turn: a single sample, a
/// block of 2 or 3 consecutive samples moved by the same offset, and a single sample next to a gap
/// (the first or last sample of a valid run; a gap of 5-15 frames is cut beside it when it does
/// not already sit at a run end). Each offset has length `amplitude` in a uniformly random
/// direction; spikes go to random valid samples of random markers, at least 5 frames apart on a
/// marker and never inside a cut gap. The same seed gives the same spikes.
struct SpikeEvaluationOptions
{
  int count = 200;         ///< spikes (not samples) to inject; > 0
  double amplitude = 5.0;  ///< millimetres; finite and > 0
  std::uint64_t seed = 1;
  SpikeOptions detector;  ///< factor, threshold and noise floor for both methods (method ignored)
};

/// One detector's score on the corrupted take.
struct SpikeEvaluation
{
  std::string method;              ///< spikeMethodName
  int spikes = 0;                  ///< spikes placed: the count asked for unless the take had no room
  Eigen::Index injected = 0;       ///< corrupted samples (a block of 3 counts 3)
  Eigen::Index detected = 0;       ///< corrupted samples the detector flagged
  Eigen::Index falseAlarms = 0;    ///< flagged clean samples, see evaluateSpikes
  Eigen::Index cleanSamples = 0;   ///< valid samples neither corrupted nor flagged on the uncorrupted take
  Eigen::Index flaggedBefore = 0;  ///< samples the detector flags on the uncorrupted take
  double falseAlarmRate = 0.0;     ///< falseAlarms / cleanSamples
  double recall = 0.0;             ///< detected / injected
  /// Root mean square distance (mm) from their true positions of the corrupted samples the detector
  /// flagged, after replaceSpikes with all its flags; NaN when nothing was detected.
  double restoredRmse = 0.0;
};

/// Injects spikes into a copy of `take` (see SpikeEvaluationOptions) and scores the Paper and
/// Robust detectors on it, in that order. Real takes may already hold spikes, so the truth is the
/// take before injection (with the cut gaps) and a flag counts as a false alarm only when its
/// sample was not corrupted AND the same detector does not flag it on the uncorrupted take; such
/// pre-existing flags are left out of cleanSamples too. Fewer spikes than asked are injected when
/// the take has too little room (placement stops after 100 000 tries in a row find none).
/// Throws InvalidArgument for a count ≤ 0, a non-finite or non-positive amplitude, bad detector
/// options, or a take with no valid sample. O(#frames · #markers) per detector, plus O(count)
/// random tries while the take has room.
[[nodiscard]] std::vector<SpikeEvaluation> evaluateSpikes(const Take& take,
                                                          const SpikeEvaluationOptions& options);

} // namespace mocap
