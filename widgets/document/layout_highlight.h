#pragma once

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace mocap::ui {

/// What the 3D view highlights of a layout: one flag per marker of the open take, kept by the
/// layout or not, and which of them are the head reference markers it was planned with. Empty
/// when there is no layout to show.
struct LayoutHighlight
{
  std::vector<bool> kept;
  std::vector<bool> reference;

  [[nodiscard]] bool empty() const { return kept.empty(); }
  /// A highlight over a take of `markerCount` markers: a flag per marker or none, since anything
  /// else belongs to another take (then no highlight; no reference flags without kept ones).
  [[nodiscard]] static LayoutHighlight forTake(std::vector<bool> kept, std::vector<bool> reference,
                                               Eigen::Index markerCount)
  {
    if (static_cast<Eigen::Index>(kept.size()) != markerCount)
      kept.clear();
    if (kept.empty() || reference.size() != kept.size())
      reference.clear();
    return {std::move(kept), std::move(reference)};
  }
};

} // namespace mocap::ui
