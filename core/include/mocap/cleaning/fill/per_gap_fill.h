#pragma once

#include "mocap/base/job_control.h"
#include "mocap/cleaning/fill/gap_fill.h"
#include "mocap/model/gaps.h"
#include "mocap/model/take.h"

#include <vector>

namespace mocap {

/// `options` with the rules of checkFillRules lifted but the one nothing lifts (a marker never
/// valid): gaps of any length, edge gaps extrapolated, markers however rarely seen. The fill a
/// user asked for past the rules, and the one an evaluation measures a method with. O(1).
[[nodiscard]] FillOptions withoutFillRules(FillOptions options);

/// Whether `a` and `b` hold the same rules (longest gap, extrapolation, least seen: the fields
/// fillEachGap takes from its `rules`), so a fill made under one holds under the other. O(1).
[[nodiscard]] bool sameFillRules(const FillOptions& a, const FillOptions& b);

/// Fills each of `gaps` with its own method, methods[i]: a gap with pastRules[i] false obeys
/// the rules of `rules` (checkFillRules decides, inside fillGaps), one with pastRules[i] true is
/// filled past them (withoutFillRules). The neighbours stay each method's default, so a gap fills
/// as fillGaps fills it alone. One fillGaps call per method and rule choice (pca models the take
/// once per call); each gap is filled from the take's valid samples only, so the grouping changes
/// no fill. Reports follow `gaps`; patches are sorted by marker, then first frame. A group whose
/// fill throws (e.g. a sample that is not finite) reports each of its gaps open with cause Method
/// and the error as reason; cancelling `job` throws JobCancelled. No gap gives an empty result.
/// Throws InvalidArgument when `methods` or `pastRules` differ in length from `gaps`.
/// Cost: that of fillGaps per group.
[[nodiscard]] FillResult fillEachGap(const Take& take, const std::vector<Gap>& gaps,
                                     const std::vector<FillMethod>& methods, const std::vector<bool>& pastRules,
                                     const FillOptions& rules, const JobControl& job = {});

} // namespace mocap
