#pragma once

#include <Eigen/Core>

#include <QString>

#include <memory>
#include <vector>

namespace mocap {
struct HeadMotion;
}

namespace mocap::ui {

class TakeDocument;

/// Where the 3D view draws a document's markers: as captured (the lab frame) or, in the
/// head-stabilized view, relative to the head pose estimated from reference markers
/// (head_stabilization.h), so only facial motion remains. What the marker layers, the camera
/// framing and head follow all draw and aim by. A view setting: the take is not changed.
class DrawnPositions
{
public:
  explicit DrawnPositions(const TakeDocument& document) : m_document(document) {}

  /// Stabilizes on these reference markers; empty = the lab frame. Returns an error message (the
  /// positions are then unchanged) or an empty string. The head motion is the document's cached one.
  QString setHeadReference(std::vector<Eigen::Index> referenceMarkers);
  /// Back to the lab frame: the take was replaced or its markers shifted.
  void clear();
  [[nodiscard]] const std::vector<Eigen::Index>& headReference() const { return m_headReference; }
  /// Whether the positions are head-stabilized.
  [[nodiscard]] bool stabilized() const { return m_headMotion != nullptr; }
  /// Where marker `marker` is drawn in `frame`. O(1).
  [[nodiscard]] Eigen::Vector3d at(Eigen::Index frame, Eigen::Index marker) const;
  /// Where the markers (not hidden, not model outputs) are drawn over frames first…last, at most
  /// 500 frames sampled; each marker's first valid sample when none is valid there.
  /// O(#frames sampled · #markers).
  [[nodiscard]] std::vector<Eigen::Vector3d> over(Eigen::Index first, Eigen::Index last) const;

private:
  const TakeDocument& m_document;
  std::vector<Eigen::Index> m_headReference;
  std::shared_ptr<const HeadMotion> m_headMotion;  // shared with the document's cache
};

} // namespace mocap::ui
