#include "mocap/math/pca.h"

#include "mocap/base/error.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <string>

namespace mocap {

double PrincipalComponents::explainedFraction() const
{
  return totalVariance > 0.0 ? variances.sum() / totalVariance : 0.0;
}

PrincipalComponents computePca(const Eigen::Ref<const Eigen::MatrixXd>& data, double varianceFraction)
{
  if (data.rows() < 2)
    throw InvalidArgument("PCA needs at least two samples, got " + std::to_string(data.rows()));
  if (data.cols() < 1)
    throw InvalidArgument("PCA needs at least one feature");
  if (!(varianceFraction > 0.0 && varianceFraction <= 1.0))
    throw InvalidArgument("PCA: the variance fraction must be in (0, 1], not " +
                          std::to_string(varianceFraction));
  if (!data.allFinite())
    throw InvalidArgument("PCA: the data hold a non-finite value");

  PrincipalComponents pca;
  pca.mean = data.colwise().mean();
  const Eigen::MatrixXd centred = data.rowwise() - pca.mean;
  Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(data.cols(), data.cols());
  covariance.selfadjointView<Eigen::Lower>().rankUpdate(centred.transpose(),
                                                        1.0 / static_cast<double>(data.rows() - 1));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance.selfadjointView<Eigen::Lower>());
  if (solver.info() != Eigen::Success)
    throw InvalidArgument("PCA: the eigen decomposition did not converge");
  // Eigen sorts ascending; rounding can leave tiny negative eigenvalues, which carry no variance.
  const Eigen::VectorXd eigenvalues = solver.eigenvalues().cwiseMax(0.0);
  pca.totalVariance = eigenvalues.sum();
  if (!(pca.totalVariance > 0.0))
    throw InvalidArgument("PCA: the data have no variance");

  const Eigen::Index features = data.cols();
  Eigen::Index kept = 0;
  double explained = 0.0;
  // The last tolerance step keeps 98 % from becoming 97.9999… through rounding.
  const double target = varianceFraction * pca.totalVariance * (1.0 - 1e-12);
  while (kept < features && explained < target) {
    explained += eigenvalues(features - 1 - kept);
    ++kept;
  }
  pca.components.resize(features, kept);
  pca.variances.resize(kept);
  for (Eigen::Index c = 0; c < kept; ++c) {
    Eigen::VectorXd vector = solver.eigenvectors().col(features - 1 - c);
    Eigen::Index largest = 0;
    vector.cwiseAbs().maxCoeff(&largest);
    if (vector(largest) < 0.0)
      vector = -vector;
    pca.components.col(c) = vector;
    pca.variances(c) = eigenvalues(features - 1 - c);
  }
  return pca;
}

} // namespace mocap
