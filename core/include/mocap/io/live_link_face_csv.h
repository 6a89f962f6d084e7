#pragma once

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// The 52 ARKit blendshape names in the order Epic's Live Link Face app writes them (JawRight
/// before JawLeft, MouthRight before MouthLeft).
[[nodiscard]] const std::vector<std::string>& liveLinkFaceShapeNames();
/// The 9 rotation columns after them: HeadYaw, HeadPitch, HeadRoll, then each eye's yaw, pitch
/// and roll (radians).
[[nodiscard]] const std::vector<std::string>& liveLinkFaceRotationNames();

/// A recording as the app writes it: one row per sample, each with its timecode.
struct LiveLinkFaceRecording
{
  std::vector<std::string> timecodes;  // HH:MM:SS:FF.mmm, kept as written
  Eigen::MatrixXd weights;             // #rows × 52, in liveLinkFaceShapeNames() order
  Eigen::MatrixXd rotations;           // #rows × 9, in liveLinkFaceRotationNames() order
};

/// The Live Link Face CSV: `Timecode,BlendShapeCount,` the 52 names, the 9 rotation names; then
/// per row the timecode, 61 and the values with 10 decimals (as the app prints them), LF line
/// ends. Throws InvalidArgument when the sizes disagree or a value is not finite. O(#rows).
[[nodiscard]] std::string liveLinkFaceCsvText(const LiveLinkFaceRecording& recording);
/// Writes liveLinkFaceCsvText atomically. Throws as it and IoError.
void writeLiveLinkFaceCsv(const std::filesystem::path& path, const LiveLinkFaceRecording& recording);

/// Reads a Live Link Face CSV. The columns may come in any order but must be the app's 61 (a
/// recording with another header is refused, naming what is missing or unknown); every row needs
/// a timecode HH:MM:SS:FF.mmm, the count and 61 finite numbers. Throws FormatError naming the line.
/// O(text size).
[[nodiscard]] LiveLinkFaceRecording parseLiveLinkFaceCsv(std::string_view text, const std::string& sourceName);
/// parseLiveLinkFaceCsv of a file; IoError when it cannot be read.
[[nodiscard]] LiveLinkFaceRecording readLiveLinkFaceCsv(const std::filesystem::path& path);

/// The timecode's time in seconds: FF counts frames of the app's 60 per second, .mmm thousandths
/// of a frame. Throws InvalidArgument for text not of that form.
[[nodiscard]] double liveLinkFaceSeconds(std::string_view timecode);
/// The timecode of `seconds` in that form (60 frames per second, as the app counts).
[[nodiscard]] std::string liveLinkFaceTimecode(double seconds);
/// Samples per second of a recording: rows over the time from the first timecode to the last,
/// rounded to a whole rate when within 0.5 % of one (the app's rows drift by a thousandth of a
/// frame now and then). 0 for fewer than two rows or timecodes that do not increase.
[[nodiscard]] double liveLinkFaceRate(const LiveLinkFaceRecording& recording);

/// A recording from solved weights under ARKit names (`names`, a column each in `weights`, any
/// order and any subset of the 52: one missing is written as 0, a name the app does not have is
/// an InvalidArgument), timed from 0 at `frameRate`; `headRotation` (#rows × 3: yaw, pitch, roll
/// in radians; or #rows × 9, the head's then each eye's as liveLinkFaceRotationNames orders them,
/// as a recording carries them) or empty for zeros; eyes not given are zero. O(#rows · 61).
[[nodiscard]] LiveLinkFaceRecording liveLinkFaceRecording(const std::vector<std::string>& names,
                                                          const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                                          double frameRate,
                                                          const Eigen::Ref<const Eigen::MatrixXd>& headRotation);

} // namespace mocap
