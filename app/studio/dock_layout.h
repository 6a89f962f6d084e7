#pragma once

#include <QString>
#include <qnamespace.h>

class QDockWidget;
class QMainWindow;
class QWidget;

namespace mocap::studio {

/// Whether a dock's content scrolls (panels) or takes the dock's size (views that zoom and pan, panels
/// that scroll themselves).
enum class DockContent
{
  Scrolls,
  Fixed,
};

/// Adds to `window` a dock named `objectName` (the name its layout is saved under) holding `content`;
/// shown from the View menu, it comes to the front.
QDockWidget* addDock(QMainWindow& window, const QString& title, const QString& objectName, QWidget* content,
                     Qt::DockWidgetArea area, DockContent kind = DockContent::Scrolls);

/// Shows and raises the dock of `window` with this object name or title (any case); false when none has it.
bool raiseDock(QMainWindow& window, const QString& name);

/// Whether the dock's content is on screen: shown and, when tabbed, its tab in front. (Qt keeps a
/// dock in a tab behind another visible, moved outside the window, so isVisible() does not tell.)
[[nodiscard]] bool dockInFront(const QDockWidget& dock);

/// Sizes and centres a first-run window on the primary screen (85 % of it); false without a screen.
bool placeFirstRunWindow(QMainWindow& window);

/// Gives the side docks 16 % (left) and 30 % (right) of the width, or the width a dock that does not
/// scroll asks for to show its content whole (the Markers table's columns) when the 3D view still
/// keeps 40 % of it; and the bottom docks 26 % of the height.
void proportionDocks(QMainWindow& window);

} // namespace mocap::studio
