#pragma once

#include "mocap/model/point_set.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace mocap {

/// The rigid transform T (a proper rotation, never a reflection, then a translation) minimising
/// Σ wᵢ‖T·fromᵢ − toᵢ‖² (Kabsch 1976 with Umeyama's sign correction, so mirrored or planar
/// configurations still give a rotation). Rows of `from` and `to` correspond; `weights` (one per
/// row, ≥ 0, not all 0) defaults to all ones. With fewer than three non-collinear points the
/// rotation is not unique and one of the minimisers is returned (the identity for one point).
/// Not a paper equation (the paper has no rigid step); head stabilization and `rigid` fill use it.
/// Throws InvalidArgument when the sizes disagree, there are no points, a coordinate or weight is
/// not finite, a weight is negative, or all weights are 0. O(#points).
[[nodiscard]] Eigen::Isometry3d kabsch(const Eigen::Ref<const PointSet>& from,
                                       const Eigen::Ref<const PointSet>& to);
[[nodiscard]] Eigen::Isometry3d kabsch(const Eigen::Ref<const PointSet>& from,
                                       const Eigen::Ref<const PointSet>& to,
                                       const Eigen::Ref<const Eigen::VectorXd>& weights);

/// Root-mean-square distance ‖T·fromᵢ − toᵢ‖ over the rows (unweighted): how rigidly `to`
/// follows `from`. Throws InvalidArgument when the sizes disagree, there are no points or a
/// coordinate is not finite. Not a paper equation. O(#points).
[[nodiscard]] double rigidResidual(const Eigen::Isometry3d& transform, const Eigen::Ref<const PointSet>& from,
                                   const Eigen::Ref<const PointSet>& to);

/// The rotation part of the Kabsch solution from an accumulated cross-covariance
/// Σ wᵢ (toᵢ − c_to)(fromᵢ − c_from)ᵀ, without input checks, for inner loops that build the
/// covariance themselves. Not a paper equation. O(1).
[[nodiscard]] Eigen::Matrix3d kabschRotation(const Eigen::Matrix3d& covariance);

} // namespace mocap
