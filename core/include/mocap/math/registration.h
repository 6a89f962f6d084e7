#pragma once

#include "mocap/math/similarity_transform.h"

#include <Eigen/Core>

#include <functional>
#include <limits>

namespace mocap {

/// Centre, principal axes and size of a point set: the coarse pose that starts a registration.
struct PrincipalFrame
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< columns: largest variance first, right-handed
  double radius = 0.0;                                  ///< RMS distance of the points from the centre
};

/// The principal frame of `points` (at least one row): the eigenvectors of the scatter matrix.
/// O(#points).
[[nodiscard]] PrincipalFrame principalFrame(const Eigen::Ref<const PointSet>& points);

/// Which side of an ICP looks for its closest counterpart in each iteration.
enum class IcpPairing
{
  /// Every source point pairs with the target's closest point: the source lies on the target
  /// (markers on a face mesh).
  EachSource,
  /// Every target point pairs with the closest moved source point: the target may miss source
  /// points and hold strays (a marker template against one frame's points).
  EachTarget,
};

/// The target's closest point to a query, where the target is more than its points (a surface).
using ClosestPoint = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

struct IcpOptions
{
  IcpPairing pairing = IcpPairing::EachSource;
  int maxIterations = 40;
  /// EachSource only: the target's closest point to a moved source point (empty: the closest
  /// target point).
  ClosestPoint closest;
  /// Trimming: pairs farther apart than this × the median pair distance stay out of the fit, and
  /// fewer than three pairs left stops the iteration. ∞: every pair is fitted.
  double inlierFactor = std::numeric_limits<double>::infinity();
  /// The fitted scale is clamped to [minScale, maxScale], keeping the pairs' centroids aligned.
  double minScale = 0.0;
  double maxScale = std::numeric_limits<double>::infinity();
  /// Stops, before fitting, once the pairs' RMS distance falls by less than this fraction of the
  /// previous iteration's (0: never by error).
  double errorTolerance = 0.0;
  /// Stops, after fitting, once the transform moves by less than this: ‖ΔR‖ + |Δs| + ‖Δt‖ over
  /// (the trimming distance + 1) (0: never by change).
  double changeTolerance = 0.0;
};

struct IcpResult
{
  Similarity transform;
  /// RMS distance of the last pairs (those the last fit used) at `transform`.
  double rms = std::numeric_limits<double>::infinity();
};

/// Iterative closest point (Besl & McKay 1992) with Umeyama similarity fits (fitSimilarityLoose),
/// from `start`: pairs each point of one side with its closest counterpart (`options.pairing`),
/// optionally trims far pairs (a multiple of the median pair distance), fits, clamps the scale,
/// and repeats until a tolerance or maxIterations stops it. No paper equation.
/// O(maxIterations · #source · #target) with the brute-force closest point.
/// Throws InvalidArgument for an empty source or target, or a non-finite coordinate.
[[nodiscard]] IcpResult icp(const Eigen::Ref<const PointSet>& source, const Eigen::Ref<const PointSet>& target,
                            const Similarity& start, const IcpOptions& options);

/// One pairing of icp() at `transform`: per point of the pairing side (source rows for
/// EachSource, target rows for EachTarget), the distance to its closest counterpart. O(#source ·
/// #target) with the brute-force closest point.
[[nodiscard]] Eigen::VectorXd closestPointDistances(const Eigen::Ref<const PointSet>& source,
                                                    const Eigen::Ref<const PointSet>& target,
                                                    const Similarity& transform, const IcpOptions& options);

} // namespace mocap
