#include "panels/dock_tab_titles.h"

#include <QChildEvent>
#include <QEvent>
#include <QMainWindow>
#include <QTabBar>

namespace mocap::ui {

namespace {

void showTitlesWhole(QTabBar& tabs)
{
  tabs.setElideMode(Qt::ElideNone);
  tabs.setUsesScrollButtons(true);
}

/// Catches the tab bars a main window creates for tabbed docks (lazily, whenever docks are first
/// tabbed together) once they are polished, after the window has set them up to elide.
class DockTabBarWatcher final : public QObject
{
public:
  using QObject::QObject;

protected:
  bool eventFilter(QObject* watched, QEvent* event) override
  {
    if (event->type() == QEvent::ChildPolished)
      if (auto* tabs = qobject_cast<QTabBar*>(static_cast<QChildEvent*>(event)->child()))
        showTitlesWhole(*tabs);
    return QObject::eventFilter(watched, event);
  }
};

} // namespace

void keepDockTabTitlesWhole(QMainWindow& window)
{
  for (QTabBar* tabs : window.findChildren<QTabBar*>(Qt::FindDirectChildrenOnly))
    showTitlesWhole(*tabs);
  window.installEventFilter(new DockTabBarWatcher(&window));
}

} // namespace mocap::ui
