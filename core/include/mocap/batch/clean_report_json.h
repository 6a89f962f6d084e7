#pragma once

#include "mocap/cleaning/clean_pipeline.h"

#include <string>

namespace mocap {

/// What one cleaning did, as `mocap clean --report` writes it and `mocap.clean` returns it:
/// "input", "output", then per step ("stabilize", "spikes", "fill", "smooth") its method, what it
/// changed (flagged spikes, every gap filled or left open with the cause and reason in words,
/// samples smoothed), the valid fraction after and the model outputs left untouched. Frames are
/// numbered as the take numbers them. Keys in a fixed order, ending in a newline.
/// O(#spikes + #gaps + #markers).
[[nodiscard]] std::string cleanReportJson(const std::string& input, const std::string& output, const Take& take,
                                          const CleanOptions& options, const CleanReport& report);

} // namespace mocap
