#include "mocap/tracking/point_tracker.h"

#include "mocap/base/error.h"
#include "mocap/math/hungarian_assignment.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mocap {

namespace {

constexpr Eigen::Index kGateSampleFrames = 200;
// The closest markers decide how far a track may reach: a low quantile of nearest distances, not
// the median, so a marker whose point vanishes cannot take its close neighbour's.
constexpr double kGateQuantile = 0.1;

double nearestDistance(const PointCloud& cloud, Eigen::Index frame, Eigen::Index i)
{
  double best = std::numeric_limits<double>::infinity();
  for (Eigen::Index j = 0; j < cloud.pointCount(frame); ++j)
    if (j != i)
      best = std::min(best, (cloud.point(frame, i) - cloud.point(frame, j)).squaredNorm());
  return std::sqrt(best);
}

Eigen::Vector3d predict(const Fragment& track, MotionModel model)
{
  const auto& p = track.positions;
  const std::size_t n = p.size();
  if (model == MotionModel::ConstantAcceleration && n >= 3)
    return 3.0 * p[n - 1] - 3.0 * p[n - 2] + p[n - 3];
  if (n >= 2)
    return 2.0 * p[n - 1] - p[n - 2];
  return p[n - 1];
}

void checkCloud(const PointCloud& cloud, const TrackerOptions& options)
{
  if (!std::isfinite(options.maxSpeed) || options.maxSpeed < 0.0)
    throw InvalidArgument("tracking: --max-speed must be a finite distance ≥ 0 (0 = automatic)");
  if (cloud.frameStart.empty() || cloud.frameStart.front() != 0 ||
      cloud.frameStart.back() != static_cast<Eigen::Index>(cloud.points.size()) ||
      !std::is_sorted(cloud.frameStart.begin(), cloud.frameStart.end()))
    throw InvalidArgument("tracking: the point cloud's frame offsets are inconsistent");
  for (const Eigen::Vector3d& p : cloud.points)
    if (!p.allFinite())
      throw InvalidArgument("tracking: a point is not finite");
}

} // namespace

double automaticGate(const PointCloud& cloud)
{
  std::vector<double> distances;
  const Eigen::Index frames = cloud.frameCount();
  const Eigen::Index step = std::max<Eigen::Index>(1, frames / kGateSampleFrames);
  for (Eigen::Index f = 0; f < frames; f += step)
    if (cloud.pointCount(f) >= 2)
      for (Eigen::Index i = 0; i < cloud.pointCount(f); ++i)
        distances.push_back(nearestDistance(cloud, f, i));
  if (distances.empty())
    return std::numeric_limits<double>::infinity();
  auto low = distances.begin() + static_cast<std::ptrdiff_t>(kGateQuantile * static_cast<double>(distances.size() - 1));
  std::nth_element(distances.begin(), low, distances.end());
  return 0.5 * *low;
}

TrackingResult trackPoints(const PointCloud& cloud, const TrackerOptions& options, const JobControl& job)
{
  checkCloud(cloud, options);
  TrackingResult result;
  result.gate = options.maxSpeed > 0.0 ? options.maxSpeed : automaticGate(cloud);
  const double gate2 = std::isinf(result.gate) ? result.gate : result.gate * result.gate;
  std::vector<std::size_t> live;  // indices into result.fragments
  std::vector<std::size_t> nextLive;
  Eigen::MatrixXd cost;
  for (Eigen::Index f = 0; f < cloud.frameCount(); ++f) {
    job.checkpoint(static_cast<double>(f) / static_cast<double>(cloud.frameCount()));
    const Eigen::Index points = cloud.pointCount(f);
    const auto tracks = static_cast<Eigen::Index>(live.size());
    cost.resize(tracks, points);
    for (Eigen::Index t = 0; t < tracks; ++t) {
      const Eigen::Vector3d predicted = predict(result.fragments[live[static_cast<std::size_t>(t)]], options.model);
      for (Eigen::Index i = 0; i < points; ++i)
        cost(t, i) = (cloud.point(f, i) - predicted).squaredNorm();
    }
    const std::vector<Eigen::Index> column = assignMinimumCost(cost, gate2);
    std::vector<bool> taken(static_cast<std::size_t>(points), false);
    nextLive.clear();
    for (Eigen::Index t = 0; t < tracks; ++t) {
      const Eigen::Index i = column[static_cast<std::size_t>(t)];
      if (i == kUnassigned)
        continue;
      const std::size_t fragment = live[static_cast<std::size_t>(t)];
      result.fragments[fragment].positions.push_back(cloud.point(f, i));
      taken[static_cast<std::size_t>(i)] = true;
      nextLive.push_back(fragment);
    }
    for (Eigen::Index i = 0; i < points; ++i) {
      if (taken[static_cast<std::size_t>(i)])
        continue;
      Fragment fragment;
      fragment.first = f;
      fragment.positions.push_back(cloud.point(f, i));
      nextLive.push_back(result.fragments.size());
      result.fragments.push_back(std::move(fragment));
    }
    live.swap(nextLive);
  }
  return result;
}

} // namespace mocap
