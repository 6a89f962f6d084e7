#include "mocap/math/similarity_transform.h"

#include "mocap/base/error.h"

#include <cmath>
#include <string>

namespace mocap {

PointSet Similarity::applyToRows(const Eigen::Ref<const PointSet>& points) const
{
  return ((scale * points * rotation.transpose()).rowwise() + translation.transpose());
}

Similarity similarityThrough(const Eigen::Matrix3d& rotation, double scale, const Eigen::Vector3d& fromCentre,
                             const Eigen::Vector3d& toCentre)
{
  Similarity result{scale, rotation, Eigen::Vector3d::Zero()};
  result.translation = toCentre - result.apply(fromCentre);
  return result;
}

namespace {

// Umeyama's closed form (R from the Kabsch rotation of the cross-covariance C, s = tr(RᵀC) / Σ‖fromᵢ − from̄‖²).
// `strict` refuses what has no unique answer; otherwise one row gives the translation only and
// coincident or non-corresponding rows give scale 1.
Similarity umeyama(const Eigen::Ref<const PointSet>& from, const Eigen::Ref<const PointSet>& to, bool strict)
{
  if (from.rows() != to.rows())
    throw InvalidArgument("similarity: point sets differ in size (" + std::to_string(from.rows()) + " and " +
                          std::to_string(to.rows()) + ")");
  if (from.rows() < (strict ? 3 : 1))
    throw InvalidArgument("similarity: needs at least " + std::string(strict ? "3 corresponding points" : "one point") +
                          ", got " + std::to_string(from.rows()));
  if (!from.allFinite() || !to.allFinite())
    throw InvalidArgument("similarity: a coordinate is not finite");
  const Eigen::RowVector3d fromCentre = from.colwise().mean();
  const Eigen::RowVector3d toCentre = to.colwise().mean();
  const PointSet fromCentred = from.rowwise() - fromCentre;
  const double spread = fromCentred.squaredNorm();
  Similarity result;
  if (spread > 1e-24 * (1.0 + fromCentre.squaredNorm())) {
    const Eigen::Matrix3d covariance = (to.rowwise() - toCentre).transpose() * fromCentred;
    result.rotation = kabschRotation(covariance);
    result.scale = (result.rotation.transpose() * covariance).trace() / spread;
  } else if (strict) {
    throw InvalidArgument("similarity: the source points coincide");
  }
  if (!(result.scale > 0.0) || !std::isfinite(result.scale)) {
    if (strict)
      throw InvalidArgument("similarity: the point sets do not correspond (non-positive scale)");
    result.scale = 1.0;
  }
  return similarityThrough(result.rotation, result.scale, fromCentre.transpose(), toCentre.transpose());
}

} // namespace

Similarity fitSimilarity(const Eigen::Ref<const PointSet>& from, const Eigen::Ref<const PointSet>& to)
{
  return umeyama(from, to, true);
}

Similarity fitSimilarityLoose(const Eigen::Ref<const PointSet>& from, const Eigen::Ref<const PointSet>& to)
{
  return umeyama(from, to, false);
}

double similarityResidual(const Similarity& transform, const Eigen::Ref<const PointSet>& from,
                          const Eigen::Ref<const PointSet>& to)
{
  if (from.rows() != to.rows() || from.rows() == 0)
    throw InvalidArgument("similarity: residual needs two non-empty point sets of one size");
  return std::sqrt((transform.applyToRows(from) - to).rowwise().squaredNorm().mean());
}

} // namespace mocap
