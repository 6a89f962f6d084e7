#pragma once

class QMainWindow;

namespace mocap::ui {

/// The tabs of docks stacked in one place show their titles whole, scrolling with arrows when they
/// do not fit, rather than eliding every title: with six docks tabbed in a side dock of about
/// 320 px (the studio's first window on a 1280×800 screen) they read "Cl…", "Ga…", "Fa…". Applies
/// to the tab bars `window` has and to those it creates later (docks tabbed by the user).
/// O(#tab bars) now, O(1) per tab bar later.
void keepDockTabTitlesWhole(QMainWindow& window);

} // namespace mocap::ui
