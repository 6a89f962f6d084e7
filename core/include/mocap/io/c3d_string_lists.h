#pragma once

#include "mocap/model/c3d_parameters.h"

#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// C3D lists of more than 255 strings (a dimension is one byte) continue in `base2`, `base3`...
/// (POINT:LABELS, LABELS2...). The reader and the writer share these.

/// The strings of `base`, `base2`, `base3`... of group `group`. O(size).
[[nodiscard]] std::vector<std::string> c3dStringsAcrossParts(const C3dParameterTree& tree, std::string_view group,
                                                             const std::string& base);

/// Writes `values` as `base`, `base2`, `base3`... of at most 255 strings each and removes stale
/// higher parts left from the original file. O(size).
void setC3dStringsAcrossParts(C3dParameterTree& tree, std::string_view group, const std::string& base,
                              const std::vector<std::string>& values);

} // namespace mocap
