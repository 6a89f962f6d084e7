#include "actions/option_toggle.h"

#include <QAction>
#include <QMenu>

namespace mocap::ui {

QAction* addOptionToggle(QMenu& menu, const QString& text, SessionOption<bool>& option)
{
  QAction* action = menu.addAction(text);
  action->setCheckable(true);
  option.follow(action, [action](bool on) { action->setChecked(on); });
  QObject::connect(action, &QAction::toggled, action, [&option](bool on) { option.set(on); });
  return action;
}

} // namespace mocap::ui
