#pragma once

#include "mocap/deform/mesh_binding.h"
#include "mocap/math/similarity_transform.h"
#include "mocap/model/take.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// How source (take) displacements are scaled to the target mesh.
enum class RetargetScale
{
  Uniform,  ///< the similarity transform's single scale
  PerAxis,  ///< one scale per mesh axis: the bound points' spread over the rotated markers' spread
};

[[nodiscard]] std::string_view retargetScaleName(RetargetScale scale);
/// Every value's name, "a|b|c" (for usage texts and errors). O(#values).
[[nodiscard]] std::string retargetScaleNames();
[[nodiscard]] std::optional<RetargetScale> parseRetargetScale(std::string_view name);

/// Maps a marker displacement from the neutral frame into a control displacement on the mesh:
/// Δ_mesh = diag(axisScale)·R·Δ_take. The paper adjusts displacements by model size (§3); the
/// rotation R takes the take's axes to the mesh's.
struct Retarget
{
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d axisScale = Eigen::Vector3d::Ones();
  double uniformScale = 1.0;  ///< the similarity scale, also for converting mesh errors to take units

  [[nodiscard]] Eigen::Vector3d map(const Eigen::Vector3d& displacement) const
  {
    return axisScale.cwiseProduct(rotation * displacement);
  }
};

/// Fits the retarget from the neutral markers (#controls × 3, take units) to their bound points
/// on the rest mesh (#controls × 3, mesh units) by fitSimilarity; per-axis scales are the RMS
/// spreads of the bound points over those of the rotated markers along each mesh axis (the uniform
/// scale where an axis is flat). Throws as fitSimilarity. O(#controls).
[[nodiscard]] Retarget fitRetarget(const Eigen::Ref<const PointSet>& neutral, const Eigen::Ref<const PointSet>& bound,
                                   RetargetScale scale);

/// Positions of `markers` in `frame` (#markers × 3). O(#markers).
[[nodiscard]] PointSet markerPositions(const Take& take, Eigen::Index frame, const std::vector<Eigen::Index>& markers);

/// The neutral frame index: `frameNumber` as the take counts frames (firstFrame-based) when given,
/// otherwise the first frame in which every marker of `markers` is valid. Throws InvalidArgument
/// for a frame outside the take, a marker invalid in the chosen frame, or no complete frame.
/// O(#frames · #markers).
[[nodiscard]] Eigen::Index chooseNeutralFrame(const Take& take, const std::vector<Eigen::Index>& markers,
                                              std::optional<long long> frameNumber);

/// Removes head motion estimated from the reference markers `labels` (head_stabilization.h) when
/// `labels` is not empty, and returns their indices. Throws as markerIndices and estimateHeadMotion.
std::vector<Eigen::Index> stabilizeTake(Take& take, const std::vector<std::string>& labels);

/// Per frame the retargeted control displacements of the markers, and which are present (valid
/// and finite in that frame), from the neutral frame's positions. O(#markers).
void controlDisplacements(const Take& take, const std::vector<Eigen::Index>& markers, Eigen::Index neutralFrame,
                          const Retarget& retarget, Eigen::Index frame, PointSet& displacements,
                          std::vector<bool>& present);
/// The same from given neutral positions (#markers × 3, take units; an actor's, actor_profile.h).
/// O(#markers).
void controlDisplacements(const Take& take, const std::vector<Eigen::Index>& markers,
                          const Eigen::Ref<const PointSet>& neutral, const Retarget& retarget, Eigen::Index frame,
                          PointSet& displacements, std::vector<bool>& present);

/// The bound points' rest positions (#points × 3). O(#points).
[[nodiscard]] PointSet boundPositions(const Eigen::Ref<const MeshVertices>& vertices,
                                      const std::vector<MeshPoint>& points);

/// A binding found in a take: the bound markers, their neutral frame and the retarget, the
/// per-take set-up that FaceRig and BlendshapeSolver share.
struct BoundTake
{
  std::vector<std::string> labels;    ///< binding order
  std::vector<Eigen::Index> markers;  ///< take marker index per bound marker
  std::vector<MeshPoint> points;      ///< bound point per marker
  Eigen::Index neutral = 0;           ///< neutral frame index (0-based); −1 when the neutral was given (an actor's)
  Retarget retarget;
  PointSet neutralMarkers;            ///< the markers in the neutral frame (take units)
  PointSet boundPoints;               ///< their bound points on `rest` (mesh units)

  /// Whether `take` still has the neutral frame and every bound marker (the set-up is stale
  /// otherwise). O(#markers).
  [[nodiscard]] bool fits(const Take& take) const;
};

/// Finds `binding`'s markers in `take` (markerIndices), picks the neutral frame
/// (chooseNeutralFrame) and fits the retarget onto the bound points of `rest`. Throws
/// InvalidArgument for a binding made for another vertex count and as those functions do.
/// O(#frames · #markers).
[[nodiscard]] BoundTake bindTake(const MeshBinding& binding, const Take& take, const Eigen::Ref<const MeshVertices>& rest,
                                 std::optional<long long> neutralFrame, RetargetScale scale);

/// bindTake with the neutral positions given (#binding markers × 3 in binding order, take units;
/// an actor's neutral) instead of a neutral frame of the take: no frame of the take needs every
/// marker. Throws as bindTake and InvalidArgument for a neutral of another size. O(#markers).
[[nodiscard]] BoundTake bindTakeToNeutral(const MeshBinding& binding, const Take& take,
                                          const Eigen::Ref<const MeshVertices>& rest,
                                          const Eigen::Ref<const PointSet>& neutral, RetargetScale scale);

} // namespace mocap
