#pragma once

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace mocap {

/// Per-frame weights (#frames × #shapes, one column per name) as CSV, `Frame,Time,<shape>,…`, one
/// row per frame; frame `i` is numbered firstFrame + i and timed i / frameRate (Live Link Face's
/// layout is io/live_link_face_csv.h). Names are quoted per RFC 4180 when needed; numbers in shortest round-trip form; LF line ends.
/// Throws InvalidArgument when names and columns disagree or the rate is not positive.
/// O(#frames · #shapes).
[[nodiscard]] std::string weightsCsvText(const std::vector<std::string>& names, const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                         long long firstFrame, double frameRate);

/// Writes weightsCsvText atomically. Throws as weightsCsvText and IoError.
void writeWeightsCsv(const std::filesystem::path& path, const std::vector<std::string>& names,
                     const Eigen::Ref<const Eigen::MatrixXd>& weights, long long firstFrame, double frameRate);

} // namespace mocap
