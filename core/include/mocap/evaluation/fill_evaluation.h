#pragma once

#include "mocap/cleaning/fill/gap_fill.h"

#include <cstdint>
#include <vector>

namespace mocap {

struct FillEvaluationOptions
{
  std::vector<Eigen::Index> gapLengths{10, 30, 60, 120, 240};  ///< frames, each ≥ 1
  int copies = 50;                                             ///< corrupted copies per gap length, 1..100000
  std::uint64_t seed = 1;  ///< same seed, same take, same options: same numbers
  std::vector<FillMethod> methods = allFillMethods();
  int neighbours = 6;  ///< FillOptions::neighbours of every method
  /// Gaps per copy, in random markers and all overlapping one random frame, so several markers
  /// are missing at once; 0 = max(1, #markers / 8), at most #markers / 4 (never more than a
  /// quarter of the markers are missing in any frame, counting the take's own gaps).
  int gapsPerCopy = 0;
  /// Hide nothing where the take itself jumps (a step over ten times the marker's usual large
  /// step, e.g. a label swap, in the hidden stretch or at its borders): there the "truth" is a
  /// tracking error, not motion a fill should reproduce. False scores against such data as well.
  bool skipJumps = true;
};

/// One method's accuracy on gaps of one length. Distances in millimetres whatever the take's
/// units; NaN when no gap was filled.
struct FillScore
{
  FillMethod method = FillMethod::Auto;
  Eigen::Index gapLength = 0;
  Eigen::Index gaps = 0;      ///< hidden gaps given to the method
  Eigen::Index unfilled = 0;  ///< of those, how many it reported as not fillable
  Eigen::Index samples = 0;   ///< hidden samples of the filled gaps, over which the errors run
  double meanError = 0.0;     ///< mean Euclidean distance to the hidden truth
  double rmse = 0.0;          ///< root-mean-square distance
  double p95 = 0.0;           ///< 95th percentile distance
  double max = 0.0;           ///< largest distance
  /// Mean |v_in − v_out| at the gap borders in mm/s: the velocity across the border (border
  /// sample to first/last filled sample) against the velocity just outside it (two valid samples).
  double borderVelocityJump = 0.0;
  double trueBorderVelocityJump = 0.0;  ///< the same with the hidden truth instead of the fill
};

struct FillEvaluation
{
  std::vector<FillScore> scores;  ///< for each gap length (outer) each method, in option order
  int copies = 0;
  std::uint64_t seed = 0;
};

/// The gaps evaluateFill hides in corrupted copy `copy` (0-based) for gaps of `length` frames:
/// up to `gapsPerCopy` gaps in random markers, all overlapping one random frame, only over
/// samples valid in the take with a valid sample either side, never more than a quarter of the
/// markers missing in a frame (counting the take's own gaps) and, with skipJumps, nowhere the
/// marker jumps; fewer when the take leaves no room. Deterministic in (take, length, copy,
/// options). Throws InvalidArgument as evaluateFill does, or for a length that does not fit or
/// copy < 0. Not a paper equation. O(#frames · #markers).
[[nodiscard]] std::vector<Gap> evaluationGaps(const Take& take, Eigen::Index length, int copy,
                                              const FillEvaluationOptions& options = {});

/// The protocol of Gløersen & Federolf (2016) on `take`: for each gap length, `copies` corrupted
/// copies, each hiding gaps of that length in random markers at random times (only samples valid
/// in the take, with a valid sample either side, so every hidden gap is interior; several
/// markers missing at once, never more than a quarter in a frame, and not over jumps in the
/// take unless skipJumps is false: evaluationGaps); hidden samples become invalid
/// and NaN so no method can peek. Each copy is filled by each method (fillGaps on the hidden
/// gaps) and the fill compared with the hidden truth. Seeded and reproducible (its own
/// generator, not the standard library's distributions). Not a paper equation: it measures eqs
/// 3-7 against the baselines. Throws InvalidArgument for an empty take, fewer than four markers,
/// options out of range, or a gap length that leaves no room in the take. O(#lengths · copies ·
/// (#frames · #markers + Σ methods' cost on the hidden gaps)).
[[nodiscard]] FillEvaluation evaluateFill(const Take& take, const FillEvaluationOptions& options = {});

} // namespace mocap
