#pragma once

#include "mocap/model/take.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// OpenSim / Motion Analysis .trc marker files (PathFileType 4, "(X/Y/Z)").
///
/// Layout: line 1 `PathFileType 4 (X/Y/Z) <file>`, line 2 the header names (DataRate, CameraRate,
/// NumFrames, NumMarkers, Units, OrigDataRate, OrigDataStartFrame, OrigNumFrames), line 3 their
/// values, line 4 `Frame# Time <label> <tab> <tab> <label>...`, line 5 `X1 Y1 Z1...`, an optional
/// blank line, then one tab-separated row per frame. A missing sample is three empty cells.

/// Reads a .trc file; see parseTrc. Throws IoError when the file cannot be read.
/// O(file size + #frames · #markers).
/// Fewer data rows than NumFrames (a truncated file) is also reported in `dataLoss`.
[[nodiscard]] Take readTrc(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr,
                           std::vector<std::string>* dataLoss = nullptr);

/// Parses .trc text. Tolerates CRLF, blanks instead of tabs in the header lines, trailing tabs,
/// short rows (their last markers are missing), "NaN" cells (missing) and fewer rows than NumFrames.
/// Things it had to guess or fix (unknown units, renamed duplicate labels, row count mismatch) go
/// to `warnings`. Valid samples get state Original and residual 0, missing ones residual −1.
/// The first row's Frame# becomes firstFrame(). Throws FormatError(sourceName, "line N: ...") for
/// malformed input, including counts the text is too small to hold, so memory stays proportional
/// to the text size. O(text size + #frames · #markers).
[[nodiscard]] Take parseTrc(std::string_view text, const std::string& sourceName,
                            std::vector<std::string>* warnings = nullptr,
                            std::vector<std::string>* dataLoss = nullptr);

/// The take as .trc text with `fileName` on line 1. Numbers use the shortest form that reads back
/// to the same double, so formatTrc → parseTrc is exact; missing and non-finite samples are empty
/// cells. Tabs and line breaks in labels become spaces and surrounding blanks are dropped, as the
/// format cannot hold them. Model outputs (marker_points.h) are left out: a TRC file holds marker
/// positions only. Throws InvalidArgument when the frame numbers would overflow or the take has
/// no marker point but model outputs.
/// O(#frames · #markers).
[[nodiscard]] std::string formatTrc(const Take& take, std::string_view fileName = "take.trc");

/// Writes formatTrc(take, file name of `path`) atomically. Throws IoError. O(#frames · #markers).
void writeTrc(const Take& take, const std::filesystem::path& path);

} // namespace mocap
