#pragma once

#include "document/color_scheme.h"
#include "mocap/model/take.h"

#include <QColor>
#include <QString>

namespace mocap::ui {

/// How the views mark a sample, ranked so the most telling wins where marks meet: a made origin
/// (edited, filled) outranks an operation (smoothed), so an invented sample that was smoothed
/// never passes for a smoothed measurement. Stabilization moves whole takes and is not marked.
enum class SampleMark : std::uint8_t
{
  None = 0,
  Smoothed = 1,
  Filled = 2,
  Edited = 3,
};
inline constexpr std::size_t kSampleMarkCount = 4;

/// The mark a sample is drawn with: its origin when made, else Smoothed when smoothed. O(1).
[[nodiscard]] SampleMark primaryMark(SampleState state);
/// The second mark of a made sample that was also smoothed (Smoothed), else None. O(1).
[[nodiscard]] SampleMark secondaryMark(SampleState state);
/// The colour of a mark (None: the original samples' colour).
[[nodiscard]] QColor markColor(SampleMark mark);
/// The studio's colour for a sample state (its primary mark's), shared by the 3D and curve views.
[[nodiscard]] QColor stateColor(SampleState state);
/// The operations of `state` in words ("smoothed, stabilized"), empty when none. O(1).
[[nodiscard]] QString operationsText(SampleState state);
/// The origin and operations in words: "filled, smoothed", "measured, stabilized". O(1).
[[nodiscard]] QString stateText(SampleState state);
/// Highlight colour of selected markers.
[[nodiscard]] QColor selectionColor();

} // namespace mocap::ui
