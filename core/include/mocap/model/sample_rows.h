#pragma once

#include "mocap/model/take.h"

#include <string>

namespace mocap {

/// Appends one text row per frame: frame number, time, then x y z of every marker, fields
/// separated by `separator`; a missing (or non-finite) sample is three empty fields. The body of
/// both TRC (tab) and CSV (comma). Throws InvalidArgument when frame numbers would overflow.
/// O(#frames · #markers).
void appendSampleRows(std::string& out, const Take& take, char separator);

} // namespace mocap
