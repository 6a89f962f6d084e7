#pragma once

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace mocap {

/// The column layout of a blendshape-weight CSV.
enum class WeightsCsvLayout
{
  Plain,     ///< `Frame,Time,<shape>,…`: frame number as the take counts, time in seconds
  LiveLink,  ///< Live Link Face: `Timecode,BlendShapeCount,<shape>,…`, timecode HH:MM:SS:FF.mmm
};

/// Per-frame weights (#frames × #shapes, one column per name) as CSV, one row per frame; frame
/// `i` is numbered firstFrame + i and timed i / frameRate. The Live Link timecode counts frames at
/// the rate rounded to a whole number, with the sub-frame fraction in thousandths after the dot.
/// Names are quoted per RFC 4180 when needed; numbers in shortest round-trip form; LF line ends.
/// Throws InvalidArgument when names and columns disagree or the rate is not positive.
/// O(#frames · #shapes).
[[nodiscard]] std::string weightsCsvText(const std::vector<std::string>& names, const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                         long long firstFrame, double frameRate, WeightsCsvLayout layout);

/// Writes weightsCsvText atomically. Throws as weightsCsvText and IoError.
void writeWeightsCsv(const std::filesystem::path& path, const std::vector<std::string>& names,
                     const Eigen::Ref<const Eigen::MatrixXd>& weights, long long firstFrame, double frameRate,
                     WeightsCsvLayout layout);

} // namespace mocap
