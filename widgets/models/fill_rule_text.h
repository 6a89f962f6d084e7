#pragma once

#include "mocap/cleaning/fill/gap_fill.h"

#include <QString>

namespace mocap::ui {

/// A time in seconds as a technician writes it: "0.5 s" (no trailing zeros). O(1).
[[nodiscard]] QString secondsText(double seconds);

/// Why a gap is left open, in the studio's words, for the Cleaning panel's fill step and the Gaps
/// dock alike: "over the 0.5 s limit", "marker seen in 8 % of the take", "at the take's end: no
/// extrapolation", "marker never seen"; a method's own reason as it gave it. `options` are the
/// rules the report was made with (mocap::checkFillRules or fillGaps). O(#frames) for a rarely
/// seen marker (its valid samples are counted), else O(1).
[[nodiscard]] QString fillRuleText(const GapFillReport& report, const Take& take, const FillOptions& options);

} // namespace mocap::ui
