#pragma once

#include "mocap/model/take.h"

#include <filesystem>
#include <string>

namespace mocap {

/// The take's marker trajectories as CSV for spreadsheets and scripts: header
/// `Frame,Time,<label>:X,<label>:Y,<label>:Z,...`, then one row per frame with Frame = firstFrame +
/// index and Time = index / rate in seconds. A missing (or non-finite) sample is three empty cells.
/// Header fields holding a comma, quote or line break are quoted per RFC 4180. Numbers use the
/// shortest form that reads back to the same double; lines end with LF. Throws InvalidArgument
/// when the frame numbers would overflow. O(#frames · #markers).
[[nodiscard]] std::string formatCsv(const Take& take);

/// Appends one CSV field per RFC 4180: a field with a comma, quote or line break is quoted, its
/// quotes doubled. O(field).
void appendCsvField(std::string& out, const std::string& field);

/// Writes formatCsv(take) atomically. Throws IoError. O(#frames · #markers).
void writeCsv(const Take& take, const std::filesystem::path& path);

} // namespace mocap
