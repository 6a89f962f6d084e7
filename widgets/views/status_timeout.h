#pragma once

namespace mocap::ui {

/// How long a status-bar message stays (ms): a hint or the outcome of an action, long enough to
/// read a sentence, gone before the next one matters.
inline constexpr int kStatusMessageMs = 5000;

} // namespace mocap::ui
