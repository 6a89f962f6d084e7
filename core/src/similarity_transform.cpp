#include "mocap/similarity_transform.h"

#include "mocap/error.h"

#include <cmath>
#include <string>

namespace mocap {

PointSet Similarity::applyToRows(const Eigen::Ref<const PointSet>& points) const
{
  return ((scale * points * rotation.transpose()).rowwise() + translation.transpose());
}

Similarity fitSimilarity(const Eigen::Ref<const PointSet>& from, const Eigen::Ref<const PointSet>& to)
{
  if (from.rows() != to.rows())
    throw InvalidArgument("similarity: point sets differ in size (" + std::to_string(from.rows()) + " and " +
                          std::to_string(to.rows()) + ")");
  if (from.rows() < 3)
    throw InvalidArgument("similarity: needs at least 3 corresponding points, got " + std::to_string(from.rows()));
  if (!from.allFinite() || !to.allFinite())
    throw InvalidArgument("similarity: a coordinate is not finite");
  const Eigen::RowVector3d fromCentre = from.colwise().mean();
  const Eigen::RowVector3d toCentre = to.colwise().mean();
  const PointSet fromCentred = from.rowwise() - fromCentre;
  const double spread = fromCentred.squaredNorm();
  if (!(spread > 1e-24 * (1.0 + fromCentre.squaredNorm())))
    throw InvalidArgument("similarity: the source points coincide");
  const Eigen::Matrix3d covariance = (to.rowwise() - toCentre).transpose() * fromCentred;
  Similarity result;
  result.rotation = kabschRotation(covariance);
  result.scale = (result.rotation.transpose() * covariance).trace() / spread;
  if (!(result.scale > 0.0))
    throw InvalidArgument("similarity: the point sets do not correspond (non-positive scale)");
  result.translation = toCentre.transpose() - result.scale * result.rotation * fromCentre.transpose();
  return result;
}

double similarityResidual(const Similarity& transform, const Eigen::Ref<const PointSet>& from,
                          const Eigen::Ref<const PointSet>& to)
{
  if (from.rows() != to.rows() || from.rows() == 0)
    throw InvalidArgument("similarity: residual needs two non-empty point sets of one size");
  return std::sqrt((transform.applyToRows(from) - to).rowwise().squaredNorm().mean());
}

} // namespace mocap
