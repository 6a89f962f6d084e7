#include "mocap/head_stabilization.h"

#include "mocap/error.h"
#include "mocap/kabsch.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <string>
#include <string_view>

namespace mocap {

namespace {

void checkMarkers(const Take& take, const std::vector<Eigen::Index>& markers)
{
  if (take.empty())
    throw InvalidArgument("head stabilisation: the take is empty");
  if (markers.size() < 3)
    throw InvalidArgument("head stabilisation needs at least three reference markers, got " +
                          std::to_string(markers.size()));
  std::set<Eigen::Index> seen;
  for (const Eigen::Index m : markers) {
    if (m < 0 || m >= take.markerCount())
      throw InvalidArgument("head stabilisation: marker index " + std::to_string(m) + " out of range");
    if (!seen.insert(m).second)
      throw InvalidArgument("head stabilisation: marker " + take.label(m) + " given twice");
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
      throw InvalidArgument("head stabilisation: reference frame " + std::to_string(requested) +
                            " is outside the take (" + std::to_string(take.frameCount()) + " frames)");
    if (!allValid(requested))
      throw InvalidArgument("head stabilisation: not every reference marker is valid in frame " +
                            std::to_string(requested));
    return requested;
  }
  if (requested != -1)
    throw InvalidArgument("head stabilisation: reference frame must be −1 or a frame index");
  for (Eigen::Index f = 0; f < take.frameCount(); ++f)
    if (allValid(f))
      return f;
  throw InvalidArgument("head stabilisation: no frame where all reference markers are valid");
}

// Interpolates about the head's centre `centre` (stabilised coordinates): the centre moves on a
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

// Applies poses[f] (or its inverse) to every sample of frame f.
void transformTake(Take& take, const HeadMotion& motion, bool inverse)
{
  checkMotion(take, motion);
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    const Eigen::Isometry3d& pose = motion.poses[static_cast<std::size_t>(f)];
    const Eigen::Matrix3d rotation = inverse ? Eigen::Matrix3d(pose.linear().transpose()) : pose.linear();
    const Eigen::Vector3d translation =
        inverse ? Eigen::Vector3d(-(rotation * pose.translation())) : Eigen::Vector3d(pose.translation());
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
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
      throw InvalidArgument("head stabilisation: a valid reference sample in frame " + std::to_string(f) +
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
}

void restoreHeadMotion(Take& take, const HeadMotion& motion)
{
  transformTake(take, motion, false);
}

std::vector<Eigen::Index> guessHeadReferenceMarkers(const Take& take)
{
  const auto startsWith = [](const std::string& label, std::string_view prefix) {
    if (label.size() < prefix.size())
      return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
      if (std::tolower(static_cast<unsigned char>(label[i])) != prefix[i])
        return false;
    return true;
  };
  std::vector<Eigen::Index> markers;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    if (startsWith(take.label(m), "root") || startsWith(take.label(m), "head"))
      markers.push_back(m);
  return markers;
}

std::vector<SamplePatch> headMotionRemovalPatches(const Take& take, const HeadMotion& motion)
{
  Take stabilised = take;
  removeHeadMotion(stabilised, motion);
  std::vector<Eigen::Index> frames(static_cast<std::size_t>(take.frameCount()));
  for (Eigen::Index f = 0; f < take.frameCount(); ++f)
    frames[static_cast<std::size_t>(f)] = f;
  std::vector<SamplePatch> patches;
  patches.reserve(static_cast<std::size_t>(take.markerCount()));
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    SamplePatch patch;
    patch.marker = m;
    patch.frames = frames;
    patch.positions = stabilised.trajectory(m);
    patch.valid = take.valid().col(m);
    patch.residuals = take.residuals().col(m);
    patch.states.reserve(frames.size());
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
      patch.states.push_back(take.state(f, m));
    patches.push_back(std::move(patch));
  }
  return patches;
}

} // namespace mocap
