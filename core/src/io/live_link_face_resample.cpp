#include "mocap/io/live_link_face_resample.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace mocap {

namespace {

/// Each row's time from the first (seconds); throws unless they increase.
std::vector<double> rowSeconds(const LiveLinkFaceRecording& recording)
{
  std::vector<double> seconds;
  seconds.reserve(recording.timecodes.size());
  const double start = liveLinkFaceSeconds(recording.timecodes.front());
  for (std::size_t i = 0; i < recording.timecodes.size(); ++i) {
    seconds.push_back(liveLinkFaceSeconds(recording.timecodes[i]) - start);
    if (i > 0 && !(seconds[i] > seconds[i - 1]))
      throw InvalidArgument("Live Link Face: the timecode of row " + std::to_string(i + 1) + " (" +
                            recording.timecodes[i] + ") does not follow the row before; cannot resample");
  }
  return seconds;
}

} // namespace

LiveLinkFaceRecording resampleLiveLinkFace(const LiveLinkFaceRecording& recording, double rate)
{
  if (!(std::isfinite(rate) && rate > 0.0))
    throw InvalidArgument("Live Link Face: the rate to resample to must be finite and > 0");
  if (recording.timecodes.size() < 2)
    throw InvalidArgument("Live Link Face: a recording needs two rows or more to resample");
  const std::vector<double> seconds = rowSeconds(recording);
  const double start = liveLinkFaceSeconds(recording.timecodes.front());
  // The last time within the recording; the small slack keeps a last row that falls on it.
  const auto rows = static_cast<Eigen::Index>(std::floor(seconds.back() * rate + 1e-6)) + 1;
  LiveLinkFaceRecording out;
  out.weights.resize(rows, recording.weights.cols());
  out.rotations.resize(rows, recording.rotations.cols());
  out.timecodes.reserve(static_cast<std::size_t>(rows));
  std::size_t before = 0;  // the recorded row at or before the time
  for (Eigen::Index k = 0; k < rows; ++k) {
    const double t = std::min(static_cast<double>(k) / rate, seconds.back());
    while (before + 2 < seconds.size() && seconds[before + 1] <= t)
      ++before;
    const double share = std::clamp((t - seconds[before]) / (seconds[before + 1] - seconds[before]), 0.0, 1.0);
    const auto a = static_cast<Eigen::Index>(before);
    out.weights.row(k) = (1.0 - share) * recording.weights.row(a) + share * recording.weights.row(a + 1);
    out.rotations.row(k) = (1.0 - share) * recording.rotations.row(a) + share * recording.rotations.row(a + 1);
    out.timecodes.push_back(liveLinkFaceTimecode(start + static_cast<double>(k) / rate));
  }
  return out;
}

} // namespace mocap
