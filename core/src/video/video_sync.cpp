#include "mocap/video/video_sync.h"

#include "mocap/base/error.h"

#include <cmath>

namespace mocap {

namespace {

void checkSync(const VideoSync& sync)
{
  if (!(sync.takeRate > 0.0) || !std::isfinite(sync.takeRate) || !(sync.videoRate > 0.0) ||
      !std::isfinite(sync.videoRate))
    throw InvalidArgument("video sync: the take and video rates must be positive");
  if (!std::isfinite(sync.offset))
    throw InvalidArgument("video sync: the offset must be finite");
}

} // namespace

std::optional<Eigen::Index> videoFrameAt(const VideoSync& sync, Eigen::Index takeFrame, Eigen::Index videoFrames)
{
  checkSync(sync);
  const double seconds = static_cast<double>(takeFrame) / sync.takeRate + sync.offset;
  const double frame = std::round(seconds * sync.videoRate);
  if (!(frame >= 0.0) || frame >= static_cast<double>(videoFrames))
    return std::nullopt;
  return static_cast<Eigen::Index>(frame);
}

double offsetMatching(const VideoSync& sync, Eigen::Index takeFrame, Eigen::Index videoFrame)
{
  checkSync(sync);
  return static_cast<double>(videoFrame) / sync.videoRate - static_cast<double>(takeFrame) / sync.takeRate;
}

} // namespace mocap
