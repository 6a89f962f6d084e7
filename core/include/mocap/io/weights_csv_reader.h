#pragma once

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// Weight curves as weights_csv_writer writes them.
struct WeightCurves
{
  std::vector<std::string> names;
  Eigen::MatrixXd weights;   ///< #frames × #names
  long long firstFrame = 0;  ///< the first row's Frame
  double frameRate = 0.0;    ///< from the Time column: rows over the time they span (0 for one row)
};

/// Reads `Frame,Time,<shape>,…` (names quoted per RFC 4180 where needed), one row per frame with
/// a frame number, a time in seconds that increases, and a finite number per shape. Throws
/// FormatError naming the line and what is wrong (another header — a Live Link Face recording is
/// read by live_link_face_csv —, a missing or extra cell, a value that is not a number). O(text).
[[nodiscard]] WeightCurves parseWeightsCsv(std::string_view text, const std::string& sourceName);
/// parseWeightsCsv of a file; IoError when it cannot be read.
[[nodiscard]] WeightCurves readWeightsCsv(const std::filesystem::path& path);

} // namespace mocap
