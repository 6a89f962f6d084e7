#pragma once

#include "mocap/model/take.h"

#include <string>
#include <vector>

namespace mocap {

/// Warnings about a take that read without error but cannot be what its file meant, each saying
/// what was seen and what the studio does about it (nothing is changed: guessing would invent data):
/// - every sample of every marker marked invalid while markers hold coordinates (some writers,
///   SIMI's among them, set residual −1 on every point): nothing will be drawn or cleaned, and a
///   saved copy holds them as the format holds invalid points (C3D: at zero), so the file is to be kept;
/// - markers whose coordinates span less than a few units in millimetres, or hundreds in metres:
///   the file's unit is likely another (a face spans about 150 mm, a body 2 m), said with the
///   unit's source (`unitDeclared` false: assumed, the file names none); judged on 3 markers or more.
/// Markers only (model outputs are angles, forces and the like). O(#frames × #markers).
[[nodiscard]] std::vector<std::string> takePlausibilityWarnings(const Take& take, bool unitDeclared);

} // namespace mocap
