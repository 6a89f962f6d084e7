#pragma once

#include "mocap/io/live_link_face_csv.h"
#include "mocap/model/take.h"

#include <Eigen/Core>

#include <algorithm>
#include <string>
#include <vector>

namespace mocap {

using StreamMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// What a live stream sends, every frame ready before the first leaves, so a send only encodes
/// (the sender's per-frame cost stays at microseconds: bench/stream_bench.cpp).
struct StreamFrames
{
  double frameRate = 0.0;     ///< the take's samples per second
  long long firstFrame = 0;   ///< the frame number of row 0
  /// #frames × 61 in liveLinkFacePacketNames() order: the 52 ARKit weights, head and eye
  /// rotations in radians; no columns when the stream carries no weights.
  StreamMatrix curves;
  std::vector<std::string> markerNames;
  /// #frames × 3·#markers: x, y, z in metres, NaN where the take has no sample; no columns
  /// without markers.
  StreamMatrix markers;

  [[nodiscard]] Eigen::Index frameCount() const { return std::max(curves.rows(), markers.rows()); }
  [[nodiscard]] bool hasCurves() const { return curves.cols() > 0; }
  [[nodiscard]] bool hasMarkers() const { return markers.cols() > 0; }
};

/// The recording's 52 weights and 9 rotations in the packet's order. Throws InvalidArgument for
/// a rate that is not positive or sizes that disagree. O(#rows · 61).
[[nodiscard]] StreamFrames streamFramesFromRecording(const LiveLinkFaceRecording& recording, double frameRate,
                                                     long long firstFrame);

/// Adds the take's markers to `frames` in metres (a missing sample NaN). Throws InvalidArgument
/// when `frames` already has curves for another number of frames. O(#frames · #markers).
void addStreamMarkers(StreamFrames& frames, const Take& take);

} // namespace mocap
