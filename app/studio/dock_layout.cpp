#include "dock_layout.h"

#include "panels/form_wrapping.h"

#include <QAction>
#include <QDockWidget>
#include <QGuiApplication>
#include <QMainWindow>
#include <QScreen>
#include <QScrollArea>
#include <QTabBar>

namespace mocap::studio {

QDockWidget* addDock(QMainWindow& window, const QString& title, const QString& objectName, QWidget* content,
                     Qt::DockWidgetArea area, DockContent kind)
{
  auto* dock = new QDockWidget(title, &window);
  dock->setObjectName(objectName);
  if (kind == DockContent::Scrolls) {
    // A panel scrolls rather than making the window taller or wider than the screen (e.g. 1280×800):
    // the window's minimum size is the sum of its docks' minimum sizes.
    auto* scroll = new QScrollArea(dock);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(content);
    ui::wrapLongFormRows(*content);  // nor sideways
    dock->setWidget(scroll);
  } else {
    dock->setWidget(content);
  }
  window.addDockWidget(area, dock);
  // Shown from the View menu, a dock comes to the front, not in a tab behind the others.
  QObject::connect(dock->toggleViewAction(), &QAction::triggered, dock, [dock](bool shown) {
    if (shown)
      dock->raise();
  });
  return dock;
}

bool raiseDock(QMainWindow& window, const QString& name)
{
  for (QDockWidget* dock : window.findChildren<QDockWidget*>())
    if (dock->objectName().compare(name, Qt::CaseInsensitive) == 0 ||
        dock->windowTitle().compare(name, Qt::CaseInsensitive) == 0) {
      dock->show();
      dock->raise();
      // A tabified dock shown while the window was hidden may not take its tab's place on
      // raise(); its tab then brings it forward.
      for (QTabBar* tabs : window.findChildren<QTabBar*>())
        for (int i = 0; i < tabs->count(); ++i)
          if (tabs->tabText(i) == dock->windowTitle() && tabs->isVisible())
            tabs->setCurrentIndex(i);
      return true;
    }
  return false;
}

bool dockInFront(const QDockWidget& dock)
{
  if (!dock.isVisible())
    return false;
  if (dock.isFloating())
    return true;
  const QWidget* window = dock.window();
  return QRect(dock.mapTo(window, QPoint(0, 0)), dock.size()).intersects(window->rect());
}

bool placeFirstRunWindow(QMainWindow& window)
{
  const QScreen* screen = QGuiApplication::primaryScreen();
  if (!screen)
    return false;
  const QRect available = screen->availableGeometry();
  const QSize size(available.width() * 85 / 100, available.height() * 85 / 100);
  window.resize(size);
  window.move(available.center() - QPoint(size.width() / 2, size.height() / 2));
  return true;
}

namespace {

/// The width a side dock's content asks for beyond its share: a panel in a scroll area wraps and
/// scrolls, and tabbed docks share their place, so only a dock of its own whose content sizes
/// itself (the Markers table) asks. 0 for none.
int contentWidth(const QMainWindow& window, QDockWidget& dock)
{
  if (qobject_cast<const QScrollArea*>(dock.widget()) || !window.tabifiedDockWidgets(&dock).isEmpty())
    return 0;
  return dock.sizeHint().width();
}

} // namespace

void proportionDocks(QMainWindow& window)
{
  // Side docks share under half the width and the curves under the view a quarter of the height;
  // the 3D view keeps the rest. (Panels scroll, so on a small screen these shares are what counts.)
  // A table gets its columns' width beyond its share when the view still keeps 40 %.
  QList<QDockWidget*> sideDocks, bottomDocks;
  QList<int> widths, heights, asked;
  for (QDockWidget* dock : window.findChildren<QDockWidget*>()) {
    if (!dock->isVisible() || dock->isFloating())
      continue;
    const Qt::DockWidgetArea area = window.dockWidgetArea(dock);
    if (area == Qt::LeftDockWidgetArea || area == Qt::RightDockWidgetArea) {
      sideDocks.append(dock);
      widths.append(window.width() * (area == Qt::LeftDockWidgetArea ? 16 : 30) / 100);
      asked.append(contentWidth(window, *dock));
    } else if (area == Qt::BottomDockWidgetArea) {
      bottomDocks.append(dock);
      heights.append(window.height() * 26 / 100);
    }
  }
  int spare = window.width() * 60 / 100;  // the side docks' widths beyond their shares, per side
  for (const Qt::DockWidgetArea side : {Qt::LeftDockWidgetArea, Qt::RightDockWidgetArea})
    for (qsizetype i = 0; i < sideDocks.size(); ++i)
      if (window.dockWidgetArea(sideDocks[i]) == side) {
        spare -= widths[i];  // docks of one side stand side by side only when tabbed: one width
        break;
      }
  // The whole content or the share: a dock widened only part of the way still cuts a column, and
  // takes the 3D view's width for it.
  for (qsizetype i = 0; i < sideDocks.size(); ++i)
    if (const int more = asked[i] - widths[i]; more > 0 && more <= spare) {
      widths[i] = asked[i];
      spare -= more;
    }
  window.resizeDocks(sideDocks, widths, Qt::Horizontal);
  window.resizeDocks(bottomDocks, heights, Qt::Vertical);
}

} // namespace mocap::studio
