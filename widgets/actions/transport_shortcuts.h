#pragma once

class QWidget;

namespace mocap::ui {

class TakeDocument;
class TimelineWidget;

/// The transport keys as window shortcuts, working wherever the focus is in `window`: Space
/// play/pause, ←/→ a frame (Shift: 10), Home/End, PgUp/PgDn the previous/next gap, Ctrl+PgUp/PgDn
/// the previous/next bad point.
void addTransportShortcuts(QWidget& window, TakeDocument& document, TimelineWidget& timeline);

} // namespace mocap::ui
