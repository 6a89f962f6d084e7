#pragma once

#include "mocap/model/take.h"

#include <filesystem>
#include <string>

namespace mocap {

/// Encodes `take` as an Intel C3D file with float storage. Every parameter of
/// take.parameters() is kept; those the data define are updated (POINT:USED, FRAMES, SCALE,
/// RATE, DATA_START, UNITS, LABELS/LABELS2..., DESCRIPTIONS; ANALOG:USED, RATE, LABELS, SCALE,
/// OFFSET, UNITS; TRIAL:ACTUAL_START_FIELD/END_FIELD when frame numbers exceed 65535; EVENT).
/// Invalid samples are written as zeros with residual −1; valid ones keep residual and camera
/// mask. Throws InvalidArgument when the take does not fit the format (over 65535 markers, a
/// record over 32 KB). O(#frames · (#markers + #analog values per frame)).
[[nodiscard]] std::string encodeC3d(const Take& take);

/// encodeC3d written atomically to `path` (temporary file, then rename).
void writeC3d(const Take& take, const std::filesystem::path& path);

} // namespace mocap
