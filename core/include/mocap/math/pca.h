#pragma once

#include <Eigen/Core>

namespace mocap {

/// The leading principal components of a data matrix (#samples × #features).
struct PrincipalComponents
{
  Eigen::RowVectorXd mean;  ///< per-feature mean, 1 × #features
  /// #features × q orthonormal eigenvectors of the covariance, by decreasing variance; row i is
  /// feature i in component space (the vectors PFA clusters).
  Eigen::MatrixXd components;
  Eigen::VectorXd variances;   ///< the q kept eigenvalues
  double totalVariance = 0.0;  ///< trace of the covariance (all eigenvalues)

  [[nodiscard]] Eigen::Index count() const { return components.cols(); }
  /// Fraction of the total variance the kept components explain.
  [[nodiscard]] double explainedFraction() const;
};

/// PCA of `data` (#samples × #features) keeping the fewest leading components whose variances
/// sum to at least `varianceFraction` of the total: step 1 of Principal Feature Analysis
/// (Cohen et al. 2002; Wellein et al. 2007 §2, "retaining 98 % variance"). Each eigenvector's
/// largest entry is made positive, so the result is deterministic.
/// O(#samples · #features² + #features³).
/// Throws InvalidArgument for fewer than two samples, no features, a non-finite value,
/// `varianceFraction` outside (0, 1], or data without any variance.
[[nodiscard]] PrincipalComponents computePca(const Eigen::Ref<const Eigen::MatrixXd>& data,
                                             double varianceFraction);

} // namespace mocap
