#include "mocap/cleaning/fill/rigid_fill.h"

#include "mocap/base/error.h"
#include "mocap/math/kabsch.h"
#include "mocap/cleaning/fill/neighbour_selection.h"

#include <algorithm>

namespace mocap {

namespace {

// The cluster's rigid motion from `reference` to each frame of `frames` (weighted Kabsch fits).
std::vector<Eigen::Isometry3d> clusterMotion(const GapQuery& gap, const std::vector<Eigen::Index>& cluster,
                                             Eigen::Index reference, const std::vector<Eigen::Index>& frames)
{
  const auto count = static_cast<Eigen::Index>(cluster.size());
  PointSet from(count, 3);
  Eigen::VectorXd weights(count);
  const Eigen::RowVector3d origin = gap.at(reference);
  for (Eigen::Index i = 0; i < count; ++i) {
    from.row(i) = gap.take.trajectory(cluster[static_cast<std::size_t>(i)]).row(reference);
    weights(i) = (from.row(i) - origin).squaredNorm();
  }
  // 1/d² favours the local motion; the floor keeps a marker sitting on the missing one finite.
  const double floor = 1e-6 * std::max(weights.mean(), 1e-300);
  weights = (weights.array() + floor).inverse().matrix();
  weights /= weights.sum();
  const Eigen::RowVector3d fromCentre = weights.transpose() * from;
  // Σ wₖ (qₖ − c)(pₖ − c̄)ᵀ = Σ qₖ · wₖ(pₖ − c̄)ᵀ: the weighted centred reference is enough.
  const PointSet weighted = weights.asDiagonal() * (from.rowwise() - fromCentre);
  std::vector<Eigen::Isometry3d> motion;
  motion.reserve(frames.size());
  std::vector<const double*> columns;
  for (const Eigen::Index j : cluster)
    columns.push_back(gap.take.trajectory(j).data());
  const Eigen::Index stride = gap.take.frameCount();
  for (const Eigen::Index f : frames) {
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    Eigen::Vector3d toCentre = Eigen::Vector3d::Zero();
    for (Eigen::Index k = 0; k < count; ++k) {
      const double* column = columns[static_cast<std::size_t>(k)] + f;
      const Eigen::Vector3d q(column[0], column[stride], column[2 * stride]);
      covariance.noalias() += q * weighted.row(k);
      toCentre += weights(k) * q;
    }
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = kabschRotation(covariance);
    pose.translation() = toCentre - pose.linear() * fromCentre.transpose();
    motion.push_back(pose);
  }
  return motion;
}

} // namespace

GapPrediction predictRigid(const GapQuery& gap, int neighbours, Eigen::Index step)
{
  if (step < 1)
    throw InvalidArgument("rigid fill: the frame step must be at least 1");
  const Eigen::Index before = gap.before();
  const Eigen::Index after = gap.after();
  if (before < 0 && after < 0)
    return GapPrediction::failure("the marker has no valid sample");
  std::vector<Eigen::Index> borders;
  if (before >= 0)
    borders.push_back(before);
  if (after >= 0)
    borders.push_back(after);
  const auto candidates = markersValidThrough(gap.take, gap.marker, borders.front(), borders.back());
  const auto cluster = nearestMarkers(gap.take, gap.marker, candidates, borders,
                                      static_cast<std::size_t>(std::max(3, neighbours)));
  if (cluster.size() < 3)
    return GapPrediction::failure("fewer than three other markers are valid through the gap and its borders");
  GapPrediction prediction;
  prediction.method = "rigid";
  // One fit per frame from the first border; with two borders the frame after the gap gets one
  // too, and the backward estimate is the after-border sample carried by T_t · T_after⁻¹.
  std::vector<Eigen::Index> frames;
  for (Eigen::Index f = gap.first; f <= gap.last(); f += step)
    frames.push_back(f);
  const auto rows = static_cast<Eigen::Index>(frames.size());
  if (before >= 0 && after >= 0)
    frames.push_back(after);
  const auto motion = clusterMotion(gap, cluster, borders.front(), frames);
  const Eigen::Vector3d start = gap.at(borders.front()).transpose();
  prediction.positions.resize(rows, 3);
  if (before < 0 || after < 0) {
    for (Eigen::Index i = 0; i < rows; ++i)
      prediction.positions.row(i) = (motion[static_cast<std::size_t>(i)] * start).transpose();
    return prediction;
  }
  const Eigen::Vector3d end = motion.back().inverse() * gap.at(after).transpose();
  const double span = static_cast<double>(gap.length + 1);
  for (Eigen::Index i = 0; i < rows; ++i) {
    const double s = static_cast<double>(frames[static_cast<std::size_t>(i)] - gap.first + 1) / span;
    const Eigen::Isometry3d& pose = motion[static_cast<std::size_t>(i)];
    prediction.positions.row(i) = (pose * ((1.0 - s) * start + s * end)).transpose();
  }
  return prediction;
}

} // namespace mocap
