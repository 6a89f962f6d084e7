#pragma once

#include "mocap/take.h"

#include <string>
#include <vector>

namespace mocap {

/// The take's labels that look like head-mounted reference markers (starting with "root" or
/// "head", any case), in take order: the default for head stabilisation. O(#markers).
[[nodiscard]] std::vector<std::string> guessHeadReferenceLabels(const Take& take);

} // namespace mocap
