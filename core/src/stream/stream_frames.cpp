#include "mocap/stream/stream_frames.h"

#include "mocap/base/error.h"
#include "mocap/base/length_unit.h"
#include "mocap/stream/live_link_face_packet.h"

#include <cmath>
#include <limits>
#include <unordered_map>

namespace mocap {

namespace {

/// The packet column of each of the recording's columns (52 shapes, then 9 rotations).
std::vector<Eigen::Index> packetColumns()
{
  std::unordered_map<std::string_view, Eigen::Index> column;
  const auto& packet = liveLinkFacePacketNames();
  for (std::size_t i = 0; i < packet.size(); ++i)
    column.emplace(packet[i], static_cast<Eigen::Index>(i));
  std::vector<Eigen::Index> columns;
  for (const std::string& name : liveLinkFaceShapeNames())
    columns.push_back(column.at(name));
  for (const std::string& name : liveLinkFaceRotationNames())
    columns.push_back(column.at(name));
  return columns;
}

} // namespace

StreamFrames streamFramesFromRecording(const LiveLinkFaceRecording& recording, double frameRate, long long firstFrame)
{
  if (!(frameRate > 0.0) || !std::isfinite(frameRate))
    throw InvalidArgument("a stream needs a positive frame rate");
  const Eigen::Index rows = recording.weights.rows();
  if (recording.weights.cols() != 52 || recording.rotations.rows() != rows || recording.rotations.cols() != 9)
    throw InvalidArgument("a Live Link Face recording holds 52 weights and 9 rotations per row");
  static const std::vector<Eigen::Index> columns = packetColumns();
  StreamFrames frames;
  frames.frameRate = frameRate;
  frames.firstFrame = firstFrame;
  frames.curves.resize(rows, static_cast<Eigen::Index>(LiveLinkFaceFrame::kValues));
  for (Eigen::Index c = 0; c < 52; ++c)
    frames.curves.col(columns[static_cast<std::size_t>(c)]) = recording.weights.col(c).cast<float>();
  for (Eigen::Index c = 0; c < 9; ++c)
    frames.curves.col(columns[static_cast<std::size_t>(52 + c)]) = recording.rotations.col(c).cast<float>();
  return frames;
}

void addStreamMarkers(StreamFrames& frames, const Take& take)
{
  if (frames.hasCurves() && frames.curves.rows() != take.frameCount())
    throw InvalidArgument("the stream's weights have " + std::to_string(frames.curves.rows()) +
                          " frames and the take " + std::to_string(take.frameCount()));
  if (frames.frameRate <= 0.0)
    frames.frameRate = take.frameRate();
  const double toMetres = millimetresPer(take.units()) / 1000.0;
  frames.markerNames = take.labels();
  frames.markers.resize(take.frameCount(), 3 * take.markerCount());
  for (Eigen::Index f = 0; f < take.frameCount(); ++f)
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      const Eigen::Vector3d p = take.position(f, m);
      const bool present = take.isValid(f, m) && p.allFinite();
      for (Eigen::Index axis = 0; axis < 3; ++axis)
        frames.markers(f, 3 * m + axis) =
            present ? static_cast<float>(p(axis) * toMetres) : std::numeric_limits<float>::quiet_NaN();
    }
}

} // namespace mocap
