#include "mocap/model/point_cloud.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/number_text.h"
#include "mocap/base/text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace mocap {

namespace {

constexpr std::int64_t kMaxFrameRange = 100000000;

struct RawPoint
{
  std::int64_t frame = 0;
  Eigen::Vector3d xyz;
};

bool parseDouble(std::string_view field, double& value)
{
  return parseNumber(trim(field), value) && std::isfinite(value);
}

PointCloud groupByFrame(std::vector<RawPoint>& raw, double frameRate)
{
  PointCloud cloud;
  cloud.frameRate = frameRate;
  if (raw.empty())
    return cloud;
  std::stable_sort(raw.begin(), raw.end(), [](const RawPoint& a, const RawPoint& b) { return a.frame < b.frame; });
  const std::int64_t first = raw.front().frame;
  const auto frames = static_cast<std::size_t>(raw.back().frame - first + 1);
  cloud.frameStart.assign(frames + 1, 0);
  for (const RawPoint& p : raw)
    ++cloud.frameStart[static_cast<std::size_t>(p.frame - first) + 1];
  for (std::size_t f = 1; f <= frames; ++f)
    cloud.frameStart[f] += cloud.frameStart[f - 1];
  cloud.points.reserve(raw.size());
  for (const RawPoint& p : raw)
    cloud.points.push_back(p.xyz);
  return cloud;
}

} // namespace

PointCloud pointCloudFromTake(const Take& take, const std::vector<Eigen::Index>& markers)
{
  for (const Eigen::Index m : markers)
    if (m < 0 || m >= take.markerCount())
      throw InvalidArgument("point cloud: marker index out of range");
  PointCloud cloud;
  cloud.frameRate = take.frameRate();
  cloud.frameStart.assign(static_cast<std::size_t>(take.frameCount()) + 1, 0);
  const auto valid = take.valid();
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    for (const Eigen::Index m : markers) {
      if (!valid(f, m))
        continue;
      const Eigen::Vector3d p = take.position(f, m);
      if (!p.allFinite())
        throw InvalidArgument("point cloud: marker '" + take.label(m) + "' has a valid sample that is not finite");
      cloud.points.push_back(p);
    }
    cloud.frameStart[static_cast<std::size_t>(f) + 1] = static_cast<Eigen::Index>(cloud.points.size());
  }
  return cloud;
}

PointCloud parsePointCloudCsv(std::string_view text, const std::string& sourceName, double frameRate)
{
  if (!std::isfinite(frameRate) || frameRate <= 0.0)
    throw InvalidArgument("point cloud: the frame rate must be finite and positive");
  std::vector<RawPoint> raw;
  for (const auto& [lineNumber, line] : contentLines(text)) {
    const auto fields = split(line, ',');
    double values[4] = {0.0, 0.0, 0.0, 0.0};
    bool numeric = fields.size() == 4;
    for (std::size_t i = 0; numeric && i < 4; ++i)
      numeric = parseDouble(fields[i], values[i]);
    if (!numeric) {
      double ignored = 0.0;
      if (raw.empty() && lineNumber == 1 && !parseDouble(fields[0], ignored))
        continue;  // header
      throw FormatError(sourceName, "line " + std::to_string(lineNumber) +
                                        ": expected frame,x,y,z with finite numbers");
    }
    if (values[0] != std::floor(values[0]) || std::abs(values[0]) > 1e15)
      throw FormatError(sourceName, "line " + std::to_string(lineNumber) + ": the frame must be an integer");
    raw.push_back({static_cast<std::int64_t>(values[0]), Eigen::Vector3d(values[1], values[2], values[3])});
  }
  if (!raw.empty()) {
    const auto [lo, hi] = std::minmax_element(raw.begin(), raw.end(),
                                              [](const RawPoint& a, const RawPoint& b) { return a.frame < b.frame; });
    if (hi->frame - lo->frame >= kMaxFrameRange)
      throw FormatError(sourceName, "frames span more than 10^8 frames");
  }
  return groupByFrame(raw, frameRate);
}

PointCloud readPointCloudCsv(const std::filesystem::path& path, double frameRate)
{
  return parsePointCloudCsv(readFileBytes(path), path.string(), frameRate);
}

} // namespace mocap
