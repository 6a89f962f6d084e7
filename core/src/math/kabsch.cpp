#include "mocap/math/kabsch.h"

#include "mocap/base/error.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <cmath>

namespace mocap {

namespace {

void checkSets(const Eigen::Ref<const PointSet>& from, const Eigen::Ref<const PointSet>& to)
{
  if (from.rows() != to.rows())
    throw InvalidArgument("kabsch: point sets differ in size (" + std::to_string(from.rows()) + " and " +
                          std::to_string(to.rows()) + " points)");
  if (from.rows() == 0)
    throw InvalidArgument("kabsch: no points");
  if (!from.allFinite() || !to.allFinite())
    throw InvalidArgument("kabsch: a coordinate is not finite");
}

} // namespace

Eigen::Matrix3d kabschRotation(const Eigen::Matrix3d& covariance)
{
  // With C = covariance = U S Vᵀ the best rotation is U D Vᵀ, D = diag(1, 1, det(U Vᵀ)): it maps
  // the plane of the two largest singular directions by the 2-D polar factor of C there and the
  // third direction by the right-hand rule. The third right singular vector v₃ comes from the
  // closed-form eigen decomposition of CᵀC; with (a, b) spanning its orthogonal plane, Ca and Cb
  // span the image plane, whose normal and 2-D rotation angle close the formula. Exact whenever
  // the points are not collinear, several times faster than an SVD, and it handles the flat
  // configurations facial marker clusters are. The SVD stays the fallback when v₃ is ill defined.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(covariance.transpose() * covariance);
  const Eigen::Vector3d& values = eigen.eigenvalues();  // ascending
  if (values(2) > 0.0 && values(1) - values(0) > 1e-2 * values(2)) {
    const Eigen::Vector3d v3 = eigen.eigenvectors().col(0).normalized();
    const Eigen::Vector3d a =
        (eigen.eigenvectors().col(2) - v3.dot(eigen.eigenvectors().col(2)) * v3).normalized();
    const Eigen::Vector3d b = v3.cross(a);
    const Eigen::Vector3d ca = covariance * a;
    const Eigen::Vector3d cb = covariance * b;
    const Eigen::Vector3d e1 = ca.normalized();
    const Eigen::Vector3d u3 = ca.cross(cb).normalized();
    const Eigen::Vector3d e2 = u3.cross(e1);
    // The 2-D polar factor of G = [e1·Ca e1·Cb; e2·Ca e2·Cb] (e2·Ca = 0) is the rotation by the
    // angle of (G₀₀ + G₁₁, G₁₀ − G₀₁); a ↦ c·e1 + s·e2, b ↦ −s·e1 + c·e2, v3 ↦ u3 = e1 × e2.
    const Eigen::Vector2d turn = Eigen::Vector2d(e1.dot(ca) + e2.dot(cb), -e1.dot(cb)).normalized();
    const double c = turn(0);
    const double s = turn(1);
    return (c * e1 + s * e2) * a.transpose() + (c * e2 - s * e1) * b.transpose() + u3 * v3.transpose();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  const Eigen::Matrix3d& v = svd.matrixV();
  if ((u * v.transpose()).determinant() < 0.0)
    u.col(2) = -u.col(2);
  return u * v.transpose();
}

Eigen::Isometry3d kabsch(const Eigen::Ref<const PointSet>& from, const Eigen::Ref<const PointSet>& to,
                         const Eigen::Ref<const Eigen::VectorXd>& weights)
{
  checkSets(from, to);
  if (weights.size() != from.rows())
    throw InvalidArgument("kabsch: " + std::to_string(weights.size()) + " weights for " +
                          std::to_string(from.rows()) + " points");
  if (!weights.allFinite() || (weights.array() < 0.0).any())
    throw InvalidArgument("kabsch: weights must be finite and not negative");
  const double total = weights.sum();
  if (!(total > 0.0))
    throw InvalidArgument("kabsch: all weights are 0");
  const Eigen::RowVector3d fromCentre = (weights.transpose() * from) / total;
  const Eigen::RowVector3d toCentre = (weights.transpose() * to) / total;
  const Eigen::Matrix3d covariance =
      (to.rowwise() - toCentre).transpose() * weights.asDiagonal() * (from.rowwise() - fromCentre);
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.linear() = kabschRotation(covariance);
  transform.translation() = toCentre.transpose() - transform.linear() * fromCentre.transpose();
  return transform;
}

Eigen::Isometry3d kabsch(const Eigen::Ref<const PointSet>& from, const Eigen::Ref<const PointSet>& to)
{
  return kabsch(from, to, Eigen::VectorXd::Ones(from.rows()));
}

double rigidResidual(const Eigen::Isometry3d& transform, const Eigen::Ref<const PointSet>& from,
                     const Eigen::Ref<const PointSet>& to)
{
  checkSets(from, to);
  double sum = 0.0;
  for (Eigen::Index i = 0; i < from.rows(); ++i)
    sum += (transform * from.row(i).transpose() - to.row(i).transpose()).squaredNorm();
  return std::sqrt(sum / static_cast<double>(from.rows()));
}

} // namespace mocap
