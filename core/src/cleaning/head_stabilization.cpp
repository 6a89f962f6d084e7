#include "mocap/cleaning/head_stabilization.h"
#include "mocap/cleaning/head_marker_labels.h"

#include "mocap/base/error.h"
#include "mocap/base/length_unit.h"
#include "mocap/math/kabsch.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/marker_set.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <set>
#include <string>

namespace mocap {

namespace {

void checkMarkers(const Take& take, const std::vector<Eigen::Index>& markers)
{
  if (take.empty())
    throw InvalidArgument("head stabilization: the take is empty");
  if (markers.size() < 3)
    throw InvalidArgument("head stabilization needs at least three reference markers, got " +
                          std::to_string(markers.size()));
  std::set<Eigen::Index> seen;
  for (const Eigen::Index m : markers) {
    if (m < 0 || m >= take.markerCount())
      throw InvalidArgument("head stabilization: marker index " + std::to_string(m) + " out of range");
    if (!seen.insert(m).second)
      throw InvalidArgument("head stabilization: marker " + take.label(m) + " given twice");
    if (!isMarker(take, m))
      throw InvalidArgument("head stabilization: " + take.label(m) + " is a model output (" +
                            std::string(pointTypeName(take.pointType(m))) + "), not a marker");
  }
}

Eigen::Index chooseReferenceFrame(const Take& take, const std::vector<Eigen::Index>& markers,
                                  Eigen::Index requested)
{
  const auto allValid = [&](Eigen::Index f) {
    return std::all_of(markers.begin(), markers.end(), [&](Eigen::Index m) { return take.isValid(f, m); });
  };
  if (requested >= 0) {
    if (requested >= take.frameCount())
      throw InvalidArgument("head stabilization: reference frame " + std::to_string(requested) +
                            " is outside the take (" + std::to_string(take.frameCount()) + " frames)");
    if (!allValid(requested))
      throw InvalidArgument("head stabilization: not every reference marker is valid in frame " +
                            std::to_string(requested));
    return requested;
  }
  if (requested != -1)
    throw InvalidArgument("head stabilization: reference frame must be −1 or a frame index");
  for (Eigen::Index f = 0; f < take.frameCount(); ++f)
    if (allValid(f))
      return f;
  throw InvalidArgument("head stabilization: no frame where all reference markers are valid");
}

// Interpolates about the head's centre `centre` (stabilized coordinates): the centre moves on a
// straight line and the rotation turns by slerp, so a turning head does not swing through the
// origin of the capture volume as interpolating the raw translation would make it.
Eigen::Isometry3d interpolatePose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double s,
                                  const Eigen::Vector3d& centre)
{
  const Eigen::Quaterniond qa(a.linear());
  const Eigen::Quaterniond qb(b.linear());
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = qa.slerp(s, qb).toRotationMatrix();
  pose.translation() = (1.0 - s) * (a * centre) + s * (b * centre) - pose.linear() * centre;
  return pose;
}

void fillUnknownPoses(HeadMotion& motion, const Eigen::Vector3d& centre)
{
  const auto frames = static_cast<Eigen::Index>(motion.poses.size());
  Eigen::Index previous = -1;
  for (Eigen::Index f = 0; f <= frames; ++f) {
    if (f < frames && !motion.known[static_cast<std::size_t>(f)])
      continue;
    // (previous, f) is a run of unknown poses between measured ones (or the take's ends).
    for (Eigen::Index g = previous + 1; g < f; ++g) {
      auto& pose = motion.poses[static_cast<std::size_t>(g)];
      if (previous < 0)
        pose = motion.poses[static_cast<std::size_t>(f)];
      else if (f == frames)
        pose = motion.poses[static_cast<std::size_t>(previous)];
      else
        pose = interpolatePose(motion.poses[static_cast<std::size_t>(previous)],
                               motion.poses[static_cast<std::size_t>(f)],
                               static_cast<double>(g - previous) / static_cast<double>(f - previous), centre);
    }
    previous = f;
  }
}

void checkMotion(const Take& take, const HeadMotion& motion)
{
  if (static_cast<Eigen::Index>(motion.poses.size()) != take.frameCount())
    throw InvalidArgument("head motion has " + std::to_string(motion.poses.size()) + " poses for " +
                          std::to_string(take.frameCount()) + " frames");
}

// Says which samples hold head-frame values: valid ones gain Stabilized when the motion is
// removed, and every sample loses it when the motion is restored; model outputs are not positions
// and are never stabilized. O(#frames · #markers).
void markStabilized(Take& take, bool stabilized)
{
  auto states = take.states();
  const auto valid = take.valid();
  for (const Eigen::Index m : markerPoints(take))
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
      const SampleState state = SampleState::fromBits(states(f, m));
      if (stabilized && valid(f, m))
        states(f, m) = state.with(SampleOperation::Stabilized).bits();
      else if (!stabilized)
        states(f, m) = state.without(SampleOperation::Stabilized).bits();
    }
}

// Applies poses[f] (or its inverse) to every marker sample of frame f (model outputs are no
// positions and stay as they are).
void transformTake(Take& take, const HeadMotion& motion, bool inverse)
{
  checkMotion(take, motion);
  const std::vector<Eigen::Index> markers = markerPoints(take);
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    const Eigen::Isometry3d& pose = motion.poses[static_cast<std::size_t>(f)];
    const Eigen::Matrix3d rotation = inverse ? Eigen::Matrix3d(pose.linear().transpose()) : pose.linear();
    const Eigen::Vector3d translation =
        inverse ? Eigen::Vector3d(-(rotation * pose.translation())) : Eigen::Vector3d(pose.translation());
    for (const Eigen::Index m : markers) {
      auto trajectory = take.trajectory(m);
      trajectory.row(f) = (rotation * trajectory.row(f).transpose() + translation).transpose();
    }
  }
}

} // namespace

HeadMotion estimateHeadMotion(const Take& take, const std::vector<Eigen::Index>& referenceMarkers,
                              Eigen::Index referenceFrame)
{
  checkMarkers(take, referenceMarkers);
  HeadMotion motion;
  motion.referenceFrame = chooseReferenceFrame(take, referenceMarkers, referenceFrame);
  const auto count = static_cast<Eigen::Index>(referenceMarkers.size());
  PointSet reference(count, 3);
  for (Eigen::Index i = 0; i < count; ++i)
    reference.row(i) = take.position(motion.referenceFrame, referenceMarkers[static_cast<std::size_t>(i)]);
  const auto frames = static_cast<std::size_t>(take.frameCount());
  motion.poses.assign(frames, Eigen::Isometry3d::Identity());
  motion.known.assign(frames, false);
  PointSet from(count, 3);
  PointSet to(count, 3);
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    Eigen::Index used = 0;
    for (Eigen::Index i = 0; i < count; ++i) {
      const Eigen::Index m = referenceMarkers[static_cast<std::size_t>(i)];
      if (!take.isValid(f, m))
        continue;
      from.row(used) = reference.row(i);
      to.row(used) = take.position(f, m).transpose();
      ++used;
    }
    if (used < 3)
      continue;
    if (!to.topRows(used).allFinite())
      throw InvalidArgument("head stabilization: a valid reference sample in frame " + std::to_string(f) +
                            " is not finite");
    motion.poses[static_cast<std::size_t>(f)] = kabsch(from.topRows(used), to.topRows(used));
    motion.known[static_cast<std::size_t>(f)] = true;
  }
  fillUnknownPoses(motion, reference.colwise().mean().transpose());
  return motion;
}

void removeHeadMotion(Take& take, const HeadMotion& motion)
{
  transformTake(take, motion, true);
  markStabilized(take, true);
}

void restoreHeadMotion(Take& take, const HeadMotion& motion)
{
  transformTake(take, motion, false);
  markStabilized(take, false);
}

std::vector<Eigen::Index> guessHeadReferenceMarkers(const Take& take)
{
  std::vector<Eigen::Index> markers = labelledHeadMarkers(take);
  return markers.empty() ? headSizedRigidCluster(take) : markers;
}

std::vector<Eigen::Index> mostRigidCluster(const Take& take, const RigidClusterOptions& options)
{
  if (options.tolerance <= 0.0 || options.maxFrames < 2)
    throw InvalidArgument("rigid cluster: the tolerance must be > 0 and at least two frames sampled");
  // Candidates: labelled markers valid in at least half the frames (a head marker is seen nearly always).
  std::vector<Eigen::Index> candidates;
  for (const Eigen::Index m : markerPoints(take))
    if (!isUnlabelledLabel(take.label(m)) && 2 * take.valid().col(m).count() >= take.frameCount() &&
        take.frameCount() > 0)
      candidates.push_back(m);
  const auto n = static_cast<Eigen::Index>(candidates.size());
  if (n < 3)
    return {};
  // Evenly spaced frames: the spread of a distance needs the take's range of motion, not every frame.
  std::vector<Eigen::Index> frames;
  const Eigen::Index step = std::max<Eigen::Index>(1, take.frameCount() / options.maxFrames);
  for (Eigen::Index f = 0; f < take.frameCount(); f += step)
    frames.push_back(f);
  // spread(i, j): standard deviation of the distance between candidates i and j over its mean
  // (a strain: unit-free, and fair to markers far apart, whose distance noise is larger).
  constexpr double kInfinite = std::numeric_limits<double>::infinity();
  Eigen::MatrixXd spread = Eigen::MatrixXd::Constant(n, n, kInfinite);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i + 1; j < n; ++j) {
      const Eigen::Index a = candidates[static_cast<std::size_t>(i)];
      const Eigen::Index b = candidates[static_cast<std::size_t>(j)];
      double sum = 0.0, sumSquares = 0.0;
      Eigen::Index count = 0;
      for (const Eigen::Index f : frames)
        if (take.isValid(f, a) && take.isValid(f, b)) {
          const double d = (take.position(f, a) - take.position(f, b)).norm();
          if (!std::isfinite(d))
            continue;
          sum += d;
          sumSquares += d * d;
          ++count;
        }
      const double mean = count > 0 ? sum / static_cast<double>(count) : 0.0;
      if (count < 2 || !(mean > 0.0))
        continue;
      spread(i, j) = spread(j, i) =
          std::sqrt(std::max(0.0, sumSquares / static_cast<double>(count) - mean * mean)) / mean;
    }
  // Grow from the most rigid pair, adding the candidate whose worst spread to the cluster is least.
  Eigen::Index seedI = 0, seedJ = 0;
  const double best = spread.minCoeff(&seedI, &seedJ);
  if (!(best <= options.tolerance))
    return {};
  std::vector<Eigen::Index> cluster{seedI, seedJ};
  Eigen::VectorXd worst = spread.col(seedI).cwiseMax(spread.col(seedJ));
  for (;;) {
    for (const Eigen::Index c : cluster)
      worst(c) = kInfinite;
    Eigen::Index next = 0;
    if (!(worst.minCoeff(&next) <= options.tolerance))
      break;
    cluster.push_back(next);
    worst = worst.cwiseMax(spread.col(next));
  }
  if (cluster.size() < 3)
    return {};
  std::vector<Eigen::Index> markers;
  for (const Eigen::Index c : cluster)
    markers.push_back(candidates[static_cast<std::size_t>(c)]);
  std::sort(markers.begin(), markers.end());
  return markers;
}

std::vector<Eigen::Index> headSizedRigidCluster(const Take& take)
{
  // Face markers sit within about 200 mm of a headband's centre; 300 mm leaves room for a neck or
  // collar marker, and a share of 80 % for a few on the shoulders.
  constexpr double kHeadReachMillimetres = 300.0;
  constexpr double kShareWithinReach = 0.8;
  constexpr Eigen::Index kFramesSampled = 50;
  std::vector<Eigen::Index> cluster = mostRigidCluster(take);
  if (cluster.empty())
    return cluster;
  const double reach = kHeadReachMillimetres / millimetresPer(take.units());
  const Eigen::Index step = std::max<Eigen::Index>(1, take.frameCount() / kFramesSampled);
  const std::vector<Eigen::Index> markers = markerPoints(take);
  std::size_t seen = 0, within = 0;
  std::vector<double> distances;
  for (const Eigen::Index m : markers) {
    distances.clear();
    for (Eigen::Index f = 0; f < take.frameCount(); f += step) {
      if (!take.isValid(f, m))
        continue;
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      double count = 0.0;
      for (const Eigen::Index c : cluster)
        if (take.isValid(f, c)) {
          centre += take.position(f, c);
          count += 1.0;
        }
      if (count > 0.0)
        distances.push_back((take.position(f, m) - centre / count).norm());
    }
    if (distances.empty())
      continue;
    const auto middle = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 2);
    std::nth_element(distances.begin(), middle, distances.end());
    ++seen;
    if (*middle <= reach)
      ++within;
  }
  if (static_cast<double>(within) < kShareWithinReach * static_cast<double>(seen))
    cluster.clear();
  return cluster;
}

std::vector<SamplePatch> headMotionRemovalPatches(const Take& take, const HeadMotion& motion)
{
  Take stabilized = take;
  removeHeadMotion(stabilized, motion);
  std::vector<Eigen::Index> frames(static_cast<std::size_t>(take.frameCount()));
  for (Eigen::Index f = 0; f < take.frameCount(); ++f)
    frames[static_cast<std::size_t>(f)] = f;
  std::vector<SamplePatch> patches;
  const std::vector<Eigen::Index> markers = markerPoints(take);
  patches.reserve(markers.size());
  for (const Eigen::Index m : markers) {
    SamplePatch patch;
    patch.marker = m;
    patch.frames = frames;
    patch.positions = stabilized.trajectory(m);
    patch.valid = take.valid().col(m);
    patch.residuals = take.residuals().col(m);
    patch.states.reserve(frames.size());
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
      patch.states.push_back(stabilized.state(f, m));
    patches.push_back(std::move(patch));
  }
  return patches;
}

} // namespace mocap
