#pragma once

#include <QColor>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace mocap::ui {

/// The colour of the `index`-th selected marker, the same in the curve and 3D views. The first is
/// the selection colour preference (colorScheme().selection), so a single selection looks as it
/// always did; the rest are hues picked to stay apart from each other and from the sample-state
/// and layout colours. Repeats after paletteSize() markers. O(1).
[[nodiscard]] QColor selectionPaletteColor(std::size_t index);
[[nodiscard]] std::size_t paletteSize();

/// The colour of `marker` in `selection` (ascending, as TakeDocument keeps it): its position in
/// the selection picks the palette entry, so the selected markers shown together never share a
/// colour (up to paletteSize()). An invalid QColor when `marker` is not selected. O(log #selected).
[[nodiscard]] QColor selectedMarkerColor(const std::vector<Eigen::Index>& selection, Eigen::Index marker);

} // namespace mocap::ui
