#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <vector>

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

/// For a variable-frame-rate video whose frames have the times `frameTimes` (seconds from the
/// first frame, ascending; sync.videoRate is not used): the frame whose time is nearest take frame
/// `takeFrame`'s video time, or nullopt more than half a frame interval before the first frame or
/// after the last. With times i / rate it agrees with the constant-rate mapping. O(log frames).
[[nodiscard]] std::optional<Eigen::Index> videoFrameAt(const VideoSync& sync, Eigen::Index takeFrame,
                                                       const std::vector<double>& frameTimes);

/// The frame whose time in `frameTimes` (ascending, not empty) is nearest `seconds`; a tie goes
/// to the later frame. O(log frames).
[[nodiscard]] Eigen::Index nearestFrame(const std::vector<double>& frameTimes, double seconds);

/// offsetMatching for a variable-frame-rate video: video frame `videoFrame`'s time is its timestamp. O(1).
[[nodiscard]] double offsetMatching(const VideoSync& sync, Eigen::Index takeFrame, Eigen::Index videoFrame,
                                    const std::vector<double>& frameTimes);

struct Event;

/// The take's 0-based frame at event time `seconds` (C3D EVENT:TIMES count seconds from the
/// trial's start, where frame 1 is): round(seconds · rate) + 1 − the take's first frame. O(1).
[[nodiscard]] Eigen::Index takeFrameOfEvent(double seconds, double takeRate, std::int64_t firstFrame);

/// The event likeliest to mark the moment the cameras were synced: the first whose label or
/// description names "sync", "trigger", "clap", "slate" or "start" (in that order of preference,
/// case-insensitive), or nullopt. O(events · labels).
[[nodiscard]] std::optional<std::size_t> syncEventIndex(const std::vector<Event>& events);

} // namespace mocap
