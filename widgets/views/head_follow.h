#pragma once

#include <Eigen/Core>

#include <optional>
#include <vector>

class vtkRenderer;

namespace mocap::ui {

class DrawnPositions;
class TakeDocument;

/// The camera following the head: its focal point tracks the smoothed centroid of the followed
/// markers where they are drawn, keeping orientation and distance, so the face stays in view while
/// the head moves in the lab frame. The followed markers are the document's reference (head)
/// markers, the one set every panel uses, else every marker point (the whole face).
class HeadFollow
{
public:
  HeadFollow(const TakeDocument& document, const DrawnPositions& positions);

  void setOn(bool on);
  [[nodiscard]] bool on() const { return m_on; }
  /// Picks the markers to follow again from the document: its reference markers changed, the take
  /// was replaced or its markers shifted. O(#markers).
  void chooseMarkers();
  [[nodiscard]] const std::vector<Eigen::Index>& markers() const { return m_markers; }
  /// Where the camera looks in `frame` while following: the mean, over frames within ±0.2 s, of
  /// the centroid of the followed markers' drawn positions (a window mean, so scrubbing back and
  /// forth gives the same view); a frame counts only with every followed marker valid. nullopt when
  /// no such frame is near `frame`. O(window × followed markers).
  [[nodiscard]] std::optional<Eigen::Vector3d> target(Eigen::Index frame) const;
  /// While on, moves the active camera of `renderer` (position and focal point together) to look
  /// at target(frame); nothing when there is none.
  void aim(vtkRenderer& renderer, Eigen::Index frame) const;

private:
  const TakeDocument& m_document;
  const DrawnPositions& m_positions;
  std::vector<Eigen::Index> m_markers;
  bool m_on = false;
};

} // namespace mocap::ui
