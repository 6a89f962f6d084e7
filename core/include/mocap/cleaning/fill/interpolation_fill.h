#pragma once

#include "mocap/cleaning/fill/gap_prediction.h"

namespace mocap {

/// `linear`: the straight line between the valid samples either side of the gap,
/// P(t) = P(a) + (t − a)/(b − a) · (P(b) − P(a)) with a = first − 1, b = last + 1. Not a paper
/// equation (the baseline every recovery method is compared with). A gap touching the first or
/// last frame is not filled (reason given): a line needs both sides. O(length).
[[nodiscard]] GapPrediction predictLinear(const GapQuery& gap);

/// `spline`: the cubic polynomial through two valid samples either side of the gap, the border
/// samples and one ⌈length/2⌉ frames further out (or the farthest valid one of the marker's valid
/// run there, when shorter), so a cubic trajectory is reproduced exactly. A side with a single
/// valid sample lowers the degree (quadratic, or linear with one sample each side). Not a paper
/// equation (a temporal-only baseline). Gaps touching the first or last frame are not filled.
/// O(length).
[[nodiscard]] GapPrediction predictSpline(const GapQuery& gap);

} // namespace mocap
