#include "mocap/video/video_sync.h"

#include "mocap/base/error.h"
#include "mocap/base/text.h"
#include "mocap/model/take.h"

#include <algorithm>
#include <cmath>
#include <string>

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

std::optional<Eigen::Index> videoFrameAt(const VideoSync& sync, Eigen::Index takeFrame,
                                         const std::vector<double>& frameTimes)
{
  checkSync(sync);
  if (frameTimes.empty())
    return std::nullopt;
  const double seconds = static_cast<double>(takeFrame) / sync.takeRate + sync.offset;
  const std::size_t n = frameTimes.size();
  // Half an interval either side of the ends, as round() gives at a constant rate.
  const double firstHalf = n > 1 ? 0.5 * (frameTimes[1] - frameTimes[0]) : 0.5 / sync.videoRate;
  const double lastHalf = n > 1 ? 0.5 * (frameTimes[n - 1] - frameTimes[n - 2]) : 0.5 / sync.videoRate;
  if (!(seconds >= frameTimes.front() - firstHalf) || seconds >= frameTimes.back() + lastHalf)
    return std::nullopt;
  return nearestFrame(frameTimes, seconds);
}

Eigen::Index nearestFrame(const std::vector<double>& frameTimes, double seconds)
{
  const auto after = std::lower_bound(frameTimes.begin(), frameTimes.end(), seconds);
  if (after == frameTimes.begin())
    return 0;
  const auto before = std::prev(after);
  if (after == frameTimes.end() || seconds - *before < *after - seconds)
    return static_cast<Eigen::Index>(before - frameTimes.begin());
  return static_cast<Eigen::Index>(after - frameTimes.begin());
}

double offsetMatching(const VideoSync& sync, Eigen::Index takeFrame, Eigen::Index videoFrame,
                      const std::vector<double>& frameTimes)
{
  checkSync(sync);
  if (videoFrame < 0 || static_cast<std::size_t>(videoFrame) >= frameTimes.size())
    throw InvalidArgument("video sync: frame " + std::to_string(videoFrame) + " is outside the video");
  return frameTimes[static_cast<std::size_t>(videoFrame)] - static_cast<double>(takeFrame) / sync.takeRate;
}

Eigen::Index takeFrameOfEvent(double seconds, double takeRate, std::int64_t firstFrame)
{
  return static_cast<Eigen::Index>(std::llround(seconds * takeRate)) + 1 - static_cast<Eigen::Index>(firstFrame);
}

std::optional<std::size_t> syncEventIndex(const std::vector<Event>& events)
{
  for (const char* word : {"sync", "trigger", "clap", "slate", "start"})
    for (std::size_t i = 0; i < events.size(); ++i)
      if (toLower(events[i].label).find(word) != std::string::npos ||
          toLower(events[i].description).find(word) != std::string::npos)
        return i;
  return std::nullopt;
}

} // namespace mocap
