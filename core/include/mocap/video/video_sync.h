#pragma once

#include <Eigen/Core>

#include <optional>

namespace mocap {

/// How a reference video lines up with a take: video time = (take frame − first frame) / take
/// rate + offset (seconds; positive when the video started before the take). Frame indices here
/// are the take's 0-based ones (0 is its first frame).
struct VideoSync
{
  double takeRate = 100.0;  ///< Hz
  double videoRate = 30.0;  ///< frames per second of the video
  double offset = 0.0;      ///< seconds
};

/// The video frame shown at take frame `takeFrame`: round((takeFrame / takeRate + offset) ·
/// videoRate), or nullopt when that lies outside [0, videoFrames). Throws InvalidArgument for a
/// rate that is not positive and finite, or a non-finite offset. O(1).
[[nodiscard]] std::optional<Eigen::Index> videoFrameAt(const VideoSync& sync, Eigen::Index takeFrame,
                                                       Eigen::Index videoFrames);

/// The offset that shows video frame `videoFrame` at take frame `takeFrame` (the user marked the
/// same moment in both). O(1).
[[nodiscard]] double offsetMatching(const VideoSync& sync, Eigen::Index takeFrame, Eigen::Index videoFrame);

} // namespace mocap
