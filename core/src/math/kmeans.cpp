#include "mocap/math/kmeans.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace mocap {

namespace {

// k-means++: each next centre is a point drawn with probability ∝ its squared distance to the
// nearest centre so far, read from the precomputed distance matrix.
std::vector<Eigen::Index> seedCentres(const KMeansPoints& points, Eigen::Index k, Random& random)
{
  const Eigen::Index n = points.count();
  std::vector<Eigen::Index> chosen;
  chosen.reserve(static_cast<std::size_t>(k));
  std::vector<bool> taken(static_cast<std::size_t>(n), false);
  const auto take = [&](Eigen::Index i) {
    chosen.push_back(i);
    taken[static_cast<std::size_t>(i)] = true;
  };
  take(random.index(n));
  Eigen::VectorXd nearest = points.squaredDistances().col(chosen.front());
  while (static_cast<Eigen::Index>(chosen.size()) < k) {
    const double total = nearest.sum();
    Eigen::Index next = -1;
    if (total > 0.0) {
      const double target = random.uniform() * total;
      double running = 0.0;
      for (Eigen::Index i = 0; i < n && next < 0; ++i) {
        running += nearest(i);
        if (nearest(i) > 0.0 && running > target)
          next = i;
      }
      if (next < 0)  // rounding left the target past the last positive weight
        for (Eigen::Index i = n - 1; i >= 0 && next < 0; --i)
          if (nearest(i) > 0.0)
            next = i;
    } else {
      // Fewer distinct points than clusters: any point not yet a centre.
      auto skip = random.index(n - static_cast<Eigen::Index>(chosen.size()));
      for (Eigen::Index i = 0; i < n && next < 0; ++i)
        if (!taken[static_cast<std::size_t>(i)] && skip-- == 0)
          next = i;
    }
    take(next);
    nearest = nearest.cwiseMin(points.squaredDistances().col(next));
  }
  return chosen;
}

} // namespace

KMeansPoints::KMeansPoints(const Eigen::Ref<const Eigen::MatrixXd>& points)
{
  if (points.rows() < 1 || points.cols() < 1)
    throw InvalidArgument("k-means needs at least one point with at least one coordinate");
  if (!points.allFinite())
    throw InvalidArgument("k-means: a point has a non-finite coordinate");
  m_points = points.transpose();
  m_squaredNorms = m_points.colwise().squaredNorm().transpose();
  m_squaredDistances = (-2.0 * (m_points.transpose() * m_points)).colwise() + m_squaredNorms;
  m_squaredDistances.rowwise() += m_squaredNorms.transpose();
  m_squaredDistances = m_squaredDistances.cwiseMax(0.0);
  m_squaredDistances.diagonal().setZero();
}

KMeansResult kMeans(const KMeansPoints& points, Eigen::Index k, std::uint64_t seed,
                    const KMeansOptions& options)
{
  const Eigen::Index n = points.count();
  const Eigen::Index dim = points.dimension();
  if (k < 1 || k > n)
    throw InvalidArgument("k-means: k must be between 1 and the number of points (" + std::to_string(n) +
                          "), not " + std::to_string(k));
  if (options.maxIterations < 1)
    throw InvalidArgument("k-means: maxIterations must be at least 1");

  Random random(seed);
  const Eigen::MatrixXd& x = points.points();
  KMeansResult result;
  result.assignment.assign(static_cast<std::size_t>(n), -1);
  auto& assignment = result.assignment;
  // Centres by coordinate (k × dim): coordinate j of every centre is contiguous, so a point's
  // distances to all centres are dim passes over k values, which the compiler vectorises.
  Eigen::MatrixXd centres(k, dim);
  Eigen::VectorXd distance(n);  // squared distance of each point to its centre
  Eigen::VectorXd toCentres(k);
  const auto nearestCentre = [&](Eigen::Index i) {
    double* sums = toCentres.data();
    std::fill(sums, sums + k, 0.0);
    for (Eigen::Index j = 0; j < dim; ++j) {
      const double coordinate = x(j, i);
      const double* column = centres.col(j).data();
      for (Eigen::Index c = 0; c < k; ++c) {
        const double d = column[c] - coordinate;
        sums[c] += d * d;
      }
    }
    Eigen::Index best = 0;
    for (Eigen::Index c = 1; c < k; ++c)
      if (sums[c] < sums[best])
        best = c;
    distance(i) = sums[best];
    const bool changed = assignment[static_cast<std::size_t>(i)] != best;
    assignment[static_cast<std::size_t>(i)] = best;
    return changed;
  };

  // The seeds are points, so the first assignment reads the precomputed distances.
  const std::vector<Eigen::Index> seeds = seedCentres(points, k, random);
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Index best = 0;
    double bestValue = points.squaredDistances()(seeds[0], i);
    for (Eigen::Index c = 1; c < k; ++c) {
      const double value = points.squaredDistances()(seeds[static_cast<std::size_t>(c)], i);
      if (value < bestValue) {
        bestValue = value;
        best = c;
      }
    }
    assignment[static_cast<std::size_t>(i)] = best;
    distance(i) = bestValue;
  }

  Eigen::VectorXd counts(k);
  // Centres become the means of their clusters; an emptied cluster restarts at the point
  // farthest from its centre.
  const auto updateCentres = [&]() {
    centres.setZero();
    counts.setZero();
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Index c = assignment[static_cast<std::size_t>(i)];
      centres.row(c) += x.col(i).transpose();
      counts(c) += 1.0;
    }
    for (Eigen::Index c = 0; c < k; ++c) {
      if (counts(c) > 0.0) {
        centres.row(c) /= counts(c);
        continue;
      }
      Eigen::Index farthest = 0;
      distance.maxCoeff(&farthest);
      centres.row(c) = x.col(farthest).transpose();
      distance(farthest) = 0.0;  // so a second empty cluster takes another point
    }
  };
  bool changed = true;
  while (changed && result.iterations < options.maxIterations) {
    ++result.iterations;
    updateCentres();
    changed = false;
    for (Eigen::Index i = 0; i < n; ++i)
      changed = nearestCentre(i) || changed;
  }
  if (changed) {  // stopped at maxIterations: the centres become the means of the final clusters
    updateCentres();
    for (Eigen::Index i = 0; i < n; ++i)
      distance(i) =
          (centres.row(assignment[static_cast<std::size_t>(i)]).transpose() - x.col(i)).squaredNorm();
  }

  result.centres = centres.transpose();
  result.inertia = distance.sum();
  result.representatives.assign(static_cast<std::size_t>(k), -1);
  Eigen::VectorXd closest = Eigen::VectorXd::Constant(k, std::numeric_limits<double>::infinity());
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index c = assignment[static_cast<std::size_t>(i)];
    if (distance(i) < closest(c)) {
      closest(c) = distance(i);
      result.representatives[static_cast<std::size_t>(c)] = i;
    }
  }
  return result;
}

} // namespace mocap
