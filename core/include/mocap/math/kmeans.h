#pragma once

#include "mocap/base/random.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace mocap {

struct KMeansOptions
{
  int maxIterations = 100;  ///< Lloyd iterations at most; runs stop earlier once no point changes cluster
};

/// One k-means clustering.
struct KMeansResult
{
  Eigen::MatrixXd centres;               ///< dim × k, column c is the mean of cluster c
  std::vector<Eigen::Index> assignment;  ///< cluster of each point
  /// Per cluster, the member point nearest its mean: PFA's "principal feature" of the cluster;
  /// −1 for a cluster left empty (possible only with fewer distinct points than clusters).
  std::vector<Eigen::Index> representatives;
  double inertia = 0.0;  ///< Σ squared distance of each point to its centre
  int iterations = 0;    ///< Lloyd iterations run
};

/// Points prepared once for many k-means runs (PFA runs thousands on the same points): the points
/// as columns, their squared norms and every pairwise squared distance, so k-means++ seeding and
/// the first assignment cost O(#points · k) without touching coordinates. Immutable, so threads
/// may share one.
class KMeansPoints
{
public:
  /// `points` is #points × dim, one point per row. O(#points² · dim).
  /// Throws InvalidArgument for no points, no dimensions or a non-finite coordinate.
  explicit KMeansPoints(const Eigen::Ref<const Eigen::MatrixXd>& points);

  [[nodiscard]] Eigen::Index count() const { return m_points.cols(); }
  [[nodiscard]] Eigen::Index dimension() const { return m_points.rows(); }
  /// dim × #points, point i is column i.
  [[nodiscard]] const Eigen::MatrixXd& points() const { return m_points; }
  [[nodiscard]] const Eigen::VectorXd& squaredNorms() const { return m_squaredNorms; }
  [[nodiscard]] const Eigen::MatrixXd& squaredDistances() const { return m_squaredDistances; }

private:
  Eigen::MatrixXd m_points;
  Eigen::VectorXd m_squaredNorms;
  Eigen::MatrixXd m_squaredDistances;
};

/// k-means with k-means++ seeding (Arthur & Vassilvitskii 2007) drawn from `seed`, then Lloyd
/// iterations until no point changes cluster. The seeds are points, so the first assignment reads
/// the precomputed distances; later ones compute each point's distances to all centres in dim
/// passes over the centres' coordinates, which the compiler vectorises. An emptied cluster
/// restarts at the point farthest from its centre. Clustering step of PFA (Cohen et al. 2002;
/// Wellein et al. 2007 §2). The same seed gives the same result on every platform (mocap::Random,
/// no std distributions). O(#points · k · (1 + dim · iterations)).
/// Throws InvalidArgument unless 1 ≤ k ≤ #points and maxIterations ≥ 1.
[[nodiscard]] KMeansResult kMeans(const KMeansPoints& points, Eigen::Index k, std::uint64_t seed,
                                  const KMeansOptions& options = {});

} // namespace mocap
