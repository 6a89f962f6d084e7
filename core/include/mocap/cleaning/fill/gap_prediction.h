#pragma once

#include "mocap/model/take.h"

#include <string>

namespace mocap {

/// One gap as a filling method sees it: `length` missing frames of `marker` from `first`.
/// `markerValid` is the marker's validity the method may rely on: the take's own column, or a
/// copy with more samples hidden (the `auto` method's leave-out validation). Other markers'
/// validity is the take's. Methods never read a sample that is not valid.
struct GapQuery
{
  /// Throws InvalidArgument when the gap does not lie inside the take, `markerValid` (when given)
  /// has the wrong size or a frame of the gap is valid. O(length). Not a paper equation: the
  /// common input of the methods behind eqs 3-7 and their baselines.
  GapQuery(const Take& take, Eigen::Index marker, Eigen::Index first, Eigen::Index length,
           const ValidMask* markerValid = nullptr);

  const Take& take;
  Eigen::Index marker;
  Eigen::Index first;
  Eigen::Index length;
  Eigen::Map<const ValidMask> markerValid;

  [[nodiscard]] Eigen::Index last() const { return first + length - 1; }
  /// The valid sample just before the gap, or −1 when the gap starts at frame 0.
  [[nodiscard]] Eigen::Index before() const { return first > 0 ? first - 1 : -1; }
  /// The valid sample just after the gap, or −1 when the gap ends at the last frame.
  [[nodiscard]] Eigen::Index after() const { return last() + 1 < take.frameCount() ? last() + 1 : -1; }
  [[nodiscard]] bool atEdge() const { return before() < 0 || after() < 0; }
  /// The marker's position in `frame`, which must be valid for it.
  [[nodiscard]] Eigen::RowVector3d at(Eigen::Index frame) const { return take.trajectory(marker).row(frame); }
};

/// A method's answer for one gap: the positions (one row per missing frame) or why there are none.
struct GapPrediction
{
  Eigen::Matrix<double, Eigen::Dynamic, 3> positions;
  std::string reason;  ///< empty when filled
  std::string method;  ///< what produced the positions (auto names its ingredients)

  [[nodiscard]] bool filled() const { return positions.rows() > 0; }
  /// A prediction with no positions and `why` as the reason. O(1).
  [[nodiscard]] static GapPrediction failure(std::string why)
  {
    GapPrediction prediction;
    prediction.reason = std::move(why);
    return prediction;
  }
};

} // namespace mocap
