#pragma once

#include "mocap/math/kabsch.h"

#include <Eigen/Core>

namespace mocap {

/// x ↦ s·R·x + t: a rotation, a uniform scale and a translation (no reflection).
struct Similarity
{
  double scale = 1.0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  [[nodiscard]] Eigen::Vector3d apply(const Eigen::Vector3d& point) const
  {
    return scale * (rotation * point) + translation;
  }
  /// Every row of `points` mapped. O(#points).
  [[nodiscard]] PointSet applyToRows(const Eigen::Ref<const PointSet>& points) const;
};

/// The similarity with `rotation` and `scale` that takes `fromCentre` onto `toCentre`. O(1).
[[nodiscard]] Similarity similarityThrough(const Eigen::Matrix3d& rotation, double scale, const Eigen::Vector3d& fromCentre,
                                           const Eigen::Vector3d& toCentre);

/// The similarity minimising Σ‖s·R·fromᵢ + t − toᵢ‖² (Umeyama 1991: R from the Kabsch step on the
/// centred sets, s = tr(Rᵀ·C) / Σ‖fromᵢ − c_from‖² with C the cross-covariance). Not a paper
/// equation: it aligns a take's neutral frame to a mesh and gives the source→target scale by which
/// the paper adjusts displacements to model size. Throws InvalidArgument for fewer than three
/// points, sizes that differ, a non-finite coordinate or coincident `from` points. O(#points).
[[nodiscard]] Similarity fitSimilarity(const Eigen::Ref<const PointSet>& from, const Eigen::Ref<const PointSet>& to);

/// The same fit where the points may not determine it (a template neighbourhood of one or two
/// markers while labelling): one row gives the translation only, coincident or non-corresponding
/// rows scale 1. Throws InvalidArgument only for no rows, sizes that differ or a non-finite
/// coordinate. O(#points).
[[nodiscard]] Similarity fitSimilarityLoose(const Eigen::Ref<const PointSet>& from, const Eigen::Ref<const PointSet>& to);

/// Root-mean-square of ‖T(fromᵢ) − toᵢ‖ in `to` units. O(#points).
[[nodiscard]] double similarityResidual(const Similarity& transform, const Eigen::Ref<const PointSet>& from,
                                        const Eigen::Ref<const PointSet>& to);

} // namespace mocap
