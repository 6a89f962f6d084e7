#include "mocap/io/live_link_face_csv.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/number_text.h"
#include "mocap/base/text.h"

#include <cmath>
#include <cstdio>
#include <unordered_map>

namespace mocap {

namespace {

constexpr int kTimecodeRate = 60;  // the app counts timecode frames at 60 per second
constexpr Eigen::Index kShapes = 52;
constexpr Eigen::Index kRotations = 9;

/// Column index of each of the 61 names: shapes first, then rotations.
const std::unordered_map<std::string, Eigen::Index>& columnOfName()
{
  static const auto columns = [] {
    std::unordered_map<std::string, Eigen::Index> map;
    for (const std::string& name : liveLinkFaceShapeNames())
      map.emplace(name, static_cast<Eigen::Index>(map.size()));
    for (const std::string& name : liveLinkFaceRotationNames())
      map.emplace(name, static_cast<Eigen::Index>(map.size()));
    return map;
  }();
  return columns;
}

void appendFixed(std::string& out, double value)
{
  char text[64];
  std::snprintf(text, sizeof text, "%.10f", value);
  out += text;
}

/// The header's value columns, as indices into shapes-then-rotations.
std::vector<Eigen::Index> readHeader(std::string_view header, const std::string& sourceName)
{
  const std::vector<std::string_view> fields = split(trim(header), ',');
  if (fields.size() < 2 || trim(fields[0]) != "Timecode" || trim(fields[1]) != "BlendShapeCount")
    throw FormatError(sourceName, "line 1: a Live Link Face recording starts with Timecode,BlendShapeCount");
  std::vector<Eigen::Index> columns;
  std::vector<bool> seen(static_cast<std::size_t>(kShapes + kRotations), false);
  for (std::size_t i = 2; i < fields.size(); ++i) {
    const std::string name(trim(fields[i]));
    const auto found = columnOfName().find(name);
    if (found == columnOfName().end())
      throw FormatError(sourceName, "line 1: '" + name + "' is not a Live Link Face column");
    if (seen[static_cast<std::size_t>(found->second)])
      throw FormatError(sourceName, "line 1: '" + name + "' is named twice");
    seen[static_cast<std::size_t>(found->second)] = true;
    columns.push_back(found->second);
  }
  for (const auto& [name, column] : columnOfName())
    if (!seen[static_cast<std::size_t>(column)])
      throw FormatError(sourceName, "line 1: the column '" + name + "' is missing");
  return columns;
}

} // namespace

const std::vector<std::string>& liveLinkFaceShapeNames()
{
  static const std::vector<std::string> names = {
      "EyeBlinkLeft",      "EyeLookDownLeft",   "EyeLookInLeft",    "EyeLookOutLeft",    "EyeLookUpLeft",
      "EyeSquintLeft",     "EyeWideLeft",       "EyeBlinkRight",    "EyeLookDownRight",  "EyeLookInRight",
      "EyeLookOutRight",   "EyeLookUpRight",    "EyeSquintRight",   "EyeWideRight",      "JawForward",
      "JawRight",          "JawLeft",           "JawOpen",          "MouthClose",        "MouthFunnel",
      "MouthPucker",       "MouthRight",        "MouthLeft",        "MouthSmileLeft",    "MouthSmileRight",
      "MouthFrownLeft",    "MouthFrownRight",   "MouthDimpleLeft",  "MouthDimpleRight",  "MouthStretchLeft",
      "MouthStretchRight", "MouthRollLower",    "MouthRollUpper",   "MouthShrugLower",   "MouthShrugUpper",
      "MouthPressLeft",    "MouthPressRight",   "MouthLowerDownLeft", "MouthLowerDownRight", "MouthUpperUpLeft",
      "MouthUpperUpRight", "BrowDownLeft",      "BrowDownRight",    "BrowInnerUp",       "BrowOuterUpLeft",
      "BrowOuterUpRight",  "CheekPuff",         "CheekSquintLeft",  "CheekSquintRight",  "NoseSneerLeft",
      "NoseSneerRight",    "TongueOut"};
  return names;
}

const std::vector<std::string>& liveLinkFaceRotationNames()
{
  static const std::vector<std::string> names = {"HeadYaw",     "HeadPitch",    "HeadRoll",
                                                 "LeftEyeYaw",  "LeftEyePitch", "LeftEyeRoll",
                                                 "RightEyeYaw", "RightEyePitch", "RightEyeRoll"};
  return names;
}

std::string liveLinkFaceTimecode(double seconds)
{
  return timecodeText(seconds, kTimecodeRate);
}

double liveLinkFaceSeconds(std::string_view timecode)
{
  int hours = 0, minutes = 0, secs = 0, frames = 0, thousandths = 0;
  char tail = 0;
  const std::string text(timecode);
  if (std::sscanf(text.c_str(), "%2d:%2d:%2d:%2d.%3d%c", &hours, &minutes, &secs, &frames, &thousandths, &tail) != 5 ||
      text.size() != 15 || minutes > 59 || secs > 59 || frames >= kTimecodeRate || hours < 0 || minutes < 0 ||
      secs < 0 || frames < 0 || thousandths < 0)
    throw InvalidArgument("Live Link Face: '" + text + "' is not a timecode HH:MM:SS:FF.mmm");
  return hours * 3600.0 + minutes * 60.0 + secs + (frames + thousandths / 1000.0) / kTimecodeRate;
}

double liveLinkFaceRate(const LiveLinkFaceRecording& recording)
{
  const std::size_t rows = recording.timecodes.size();
  if (rows < 2)
    return 0.0;
  const double span = liveLinkFaceSeconds(recording.timecodes.back()) - liveLinkFaceSeconds(recording.timecodes.front());
  if (!(span > 0.0))
    return 0.0;
  const double rate = static_cast<double>(rows - 1) / span;
  const double whole = std::round(rate);
  return std::abs(rate - whole) <= 0.005 * whole ? whole : rate;
}

std::string liveLinkFaceCsvText(const LiveLinkFaceRecording& recording)
{
  const auto rows = static_cast<Eigen::Index>(recording.timecodes.size());
  if (recording.weights.rows() != rows || recording.weights.cols() != kShapes || recording.rotations.rows() != rows ||
      recording.rotations.cols() != kRotations)
    throw InvalidArgument("Live Link Face: each row needs a timecode, 52 weights and 9 rotations");
  if (!recording.weights.allFinite() || !recording.rotations.allFinite())
    throw InvalidArgument("Live Link Face: a weight or rotation is not finite");
  std::string out = "Timecode,BlendShapeCount";
  for (const std::string& name : liveLinkFaceShapeNames())
    out += ',' + name;
  for (const std::string& name : liveLinkFaceRotationNames())
    out += ',' + name;
  out += '\n';
  const std::string count = "," + std::to_string(kShapes + kRotations);
  for (Eigen::Index r = 0; r < rows; ++r) {
    out += recording.timecodes[static_cast<std::size_t>(r)];
    out += count;
    for (Eigen::Index s = 0; s < kShapes; ++s)
      out += ',', appendFixed(out, recording.weights(r, s));
    for (Eigen::Index s = 0; s < kRotations; ++s)
      out += ',', appendFixed(out, recording.rotations(r, s));
    out += '\n';
  }
  return out;
}

void writeLiveLinkFaceCsv(const std::filesystem::path& path, const LiveLinkFaceRecording& recording)
{
  writeFileAtomically(path, liveLinkFaceCsvText(recording));
}

LiveLinkFaceRecording parseLiveLinkFaceCsv(std::string_view text, const std::string& sourceName)
{
  const std::vector<TextLine> lines = contentLines(text);
  if (lines.empty())
    throw FormatError(sourceName, "the file is empty");
  const std::vector<Eigen::Index> columns = readHeader(lines.front().text, sourceName);
  LiveLinkFaceRecording recording;
  const auto rows = static_cast<Eigen::Index>(lines.size() - 1);
  recording.weights.resize(rows, kShapes);
  recording.rotations.resize(rows, kRotations);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const TextLine& line = lines[static_cast<std::size_t>(r + 1)];
    const std::string where = "line " + std::to_string(line.number) + ": ";
    const std::vector<std::string_view> fields = split(line.text, ',');
    if (fields.size() != columns.size() + 2)
      throw FormatError(sourceName, where + std::to_string(fields.size()) + " fields where the header has " +
                                        std::to_string(columns.size() + 2));
    try {
      (void)liveLinkFaceSeconds(trim(fields[0]));
    } catch (const InvalidArgument& error) {
      throw FormatError(sourceName, where + error.what());
    }
    recording.timecodes.emplace_back(trim(fields[0]));
    for (std::size_t i = 0; i < columns.size(); ++i) {
      double value = 0.0;
      if (!parseNumber(trim(fields[i + 2]), value) || !std::isfinite(value))
        throw FormatError(sourceName, where + "'" + std::string(fields[i + 2]) + "' is not a finite number");
      const Eigen::Index column = columns[i];
      if (column < kShapes)
        recording.weights(r, column) = value;
      else
        recording.rotations(r, column - kShapes) = value;
    }
  }
  return recording;
}

LiveLinkFaceRecording readLiveLinkFaceCsv(const std::filesystem::path& path)
{
  return parseLiveLinkFaceCsv(readFileBytes(path), path.string());
}

LiveLinkFaceRecording liveLinkFaceRecording(const std::vector<std::string>& names,
                                            const Eigen::Ref<const Eigen::MatrixXd>& weights, double frameRate,
                                            const Eigen::Ref<const Eigen::MatrixXd>& headRotation)
{
  if (static_cast<Eigen::Index>(names.size()) != weights.cols())
    throw InvalidArgument("Live Link Face: " + std::to_string(names.size()) + " names for " +
                          std::to_string(weights.cols()) + " weight columns");
  if (!(frameRate > 0.0) || !std::isfinite(frameRate))
    throw InvalidArgument("Live Link Face: the frame rate must be positive");
  if (headRotation.size() > 0 &&
      (headRotation.rows() != weights.rows() || (headRotation.cols() != 3 && headRotation.cols() != kRotations)))
    throw InvalidArgument("Live Link Face: the head rotation needs yaw, pitch and roll for every frame (and, "
                          "when given, each eye's yaw, pitch and roll after them)");
  LiveLinkFaceRecording recording;
  recording.weights = Eigen::MatrixXd::Zero(weights.rows(), kShapes);
  recording.rotations = Eigen::MatrixXd::Zero(weights.rows(), kRotations);
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto found = columnOfName().find(names[i]);
    if (found == columnOfName().end() || found->second >= kShapes)
      throw InvalidArgument("Live Link Face: '" + names[i] +
                            "' is not one of its 52 ARKit names (map the rig's shapes onto them with a retarget map)");
    recording.weights.col(found->second) = weights.col(static_cast<Eigen::Index>(i));
  }
  if (headRotation.size() > 0)
    recording.rotations.leftCols(headRotation.cols()) = headRotation;
  for (Eigen::Index f = 0; f < weights.rows(); ++f)
    recording.timecodes.push_back(liveLinkFaceTimecode(static_cast<double>(f) / frameRate));
  return recording;
}

} // namespace mocap
