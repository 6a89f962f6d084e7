#pragma once

#include "mocap/cleaning/fill/gap_prediction.h"

namespace mocap {

/// Rows of a prediction that also covers the gap's border samples: row 0 is frame first − 1,
/// rows 1..length the gap, row length + 1 frame last + 1. A missing border's row is ignored.
using BorderedTrack = Eigen::Matrix<double, Eigen::Dynamic, 3>;

/// How an offset at a gap border fades into the gap.
enum class BorderRamp
{
  Linear,  ///< s = τ: the offsets are interpolated linearly
  Smooth,  ///< s = 3τ² − 2τ³: zero slope at both borders, so the prediction's velocity is kept there
};

/// Makes `track` meet the captured marker at the gap's borders and returns the gap rows: with
/// e₀ = P(first − 1) − track(0) and e₁ = P(last + 1) − track(length + 1), gap frame t gets
/// track(t) + (1 − s)·e₀ + s·e₁, τ = (t − first + 1)/(length + 1). A gap touching the take's
/// edge has one border and gets its offset unfaded. Not a paper equation: it removes the drift
/// the forward recursions (eqs 5 and 7) leave at the far border. Throws InvalidArgument when
/// `track` does not have length + 2 rows. O(length).
[[nodiscard]] Eigen::Matrix<double, Eigen::Dynamic, 3>
blendBorders(const GapQuery& gap, const BorderedTrack& track, BorderRamp ramp = BorderRamp::Smooth);

} // namespace mocap
