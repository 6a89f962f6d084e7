#include "mocap/math/registration.h"

#include "mocap/base/error.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace mocap {

PrincipalFrame principalFrame(const Eigen::Ref<const PointSet>& points)
{
  PrincipalFrame frame;
  frame.centre = points.colwise().mean().transpose();
  const PointSet centred = points.rowwise() - frame.centre.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(centred.transpose() * centred);
  frame.axes = eigen.eigenvectors().rowwise().reverse();
  if (frame.axes.determinant() < 0.0)
    frame.axes.col(2) = -frame.axes.col(2);
  frame.radius = std::sqrt(centred.rowwise().squaredNorm().mean());
  return frame;
}

namespace {

// The row of `points` nearest to `query` (brute force: the sets are a face's markers or mesh).
Eigen::Index nearestRow(const Eigen::Ref<const PointSet>& points, const Eigen::RowVector3d& query)
{
  Eigen::Index best = 0;
  (points.rowwise() - query).rowwise().squaredNorm().minCoeff(&best);
  return best;
}

// One pairing: row i of `from` (a source point, unmoved) pairs with row i of `to` (a target point).
struct Pairs
{
  PointSet from;
  PointSet to;
  Eigen::VectorXd distances;
};

Pairs pairUp(const Eigen::Ref<const PointSet>& source, const Eigen::Ref<const PointSet>& target,
             const Similarity& transform, const IcpOptions& options)
{
  const PointSet moved = transform.applyToRows(source);
  Pairs pairs;
  if (options.pairing == IcpPairing::EachSource) {
    pairs.from = source;
    pairs.to.resize(source.rows(), 3);
    for (Eigen::Index i = 0; i < source.rows(); ++i)
      pairs.to.row(i) = options.closest ? options.closest(moved.row(i).transpose()).transpose()
                                        : Eigen::RowVector3d(target.row(nearestRow(target, moved.row(i))));
    pairs.distances = (moved - pairs.to).rowwise().norm();
  } else {
    pairs.from.resize(target.rows(), 3);
    pairs.to = target;
    pairs.distances.resize(target.rows());
    for (Eigen::Index i = 0; i < target.rows(); ++i) {
      const Eigen::Index closest = nearestRow(moved, target.row(i));
      pairs.from.row(i) = source.row(closest);
      pairs.distances(i) = (moved.row(closest) - target.row(i)).norm();
    }
  }
  return pairs;
}

// The distance below which a pair is fitted: inlierFactor × the median pair distance.
double trimmingDistance(Eigen::VectorXd distances, double inlierFactor)
{
  if (std::isinf(inlierFactor))
    return std::numeric_limits<double>::infinity();
  const auto middle = (distances.size() - 1) / 2;
  std::nth_element(distances.data(), distances.data() + middle, distances.data() + distances.size());
  return inlierFactor * distances(middle) + 1e-12;
}

// The similarity fitted to the pairs no farther apart than `limit` (nullopt: fewer than three).
std::optional<Similarity> fitPairs(const Pairs& pairs, double limit, const IcpOptions& options)
{
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < pairs.distances.size(); ++i)
    if (std::isinf(limit) || pairs.distances(i) <= limit)
      kept.push_back(i);
  if (kept.size() < 3)
    return std::nullopt;
  PointSet from(static_cast<Eigen::Index>(kept.size()), 3), to(from.rows(), 3);
  for (std::size_t k = 0; k < kept.size(); ++k) {
    from.row(static_cast<Eigen::Index>(k)) = pairs.from.row(kept[k]);
    to.row(static_cast<Eigen::Index>(k)) = pairs.to.row(kept[k]);
  }
  Similarity fit = fitSimilarityLoose(from, to);
  const double scale = std::clamp(fit.scale, options.minScale, options.maxScale);
  if (scale != fit.scale) {  // the clamped scale about the pairs' centroids
    fit.scale = scale;
    fit.translation = (to.colwise().mean() - scale * from.colwise().mean() * fit.rotation.transpose()).transpose();
  }
  return fit;
}

double change(const Similarity& a, const Similarity& b, double limit)
{
  return (b.rotation - a.rotation).norm() + std::abs(b.scale - a.scale) +
         (b.translation - a.translation).norm() / (limit + 1.0);
}

} // namespace

IcpResult icp(const Eigen::Ref<const PointSet>& source, const Eigen::Ref<const PointSet>& target,
              const Similarity& start, const IcpOptions& options)
{
  if (source.rows() == 0 || target.rows() == 0)
    throw InvalidArgument("icp: needs source and target points");
  if (!source.allFinite() || !target.allFinite())
    throw InvalidArgument("icp: a coordinate is not finite");
  IcpResult result{start, std::numeric_limits<double>::infinity()};
  Pairs pairs;
  for (int iteration = 0; iteration < options.maxIterations; ++iteration) {
    pairs = pairUp(source, target, result.transform, options);
    const double rms = similarityResidual(result.transform, pairs.from, pairs.to);
    if (options.errorTolerance > 0.0 && rms >= result.rms * (1.0 - options.errorTolerance))
      break;
    result.rms = rms;
    const double limit = trimmingDistance(pairs.distances, options.inlierFactor);
    const std::optional<Similarity> next = fitPairs(pairs, limit, options);
    if (!next)
      break;
    const double moved = change(result.transform, *next, limit);
    result.transform = *next;
    if (moved < options.changeTolerance)
      break;
  }
  if (pairs.from.rows() > 0)
    result.rms = similarityResidual(result.transform, pairs.from, pairs.to);
  return result;
}

Eigen::VectorXd closestPointDistances(const Eigen::Ref<const PointSet>& source, const Eigen::Ref<const PointSet>& target,
                                      const Similarity& transform, const IcpOptions& options)
{
  return pairUp(source, target, transform, options).distances;
}

} // namespace mocap
