#include "actions/language_menu.h"

#include "dialogs/preferences_dialog.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>

namespace mocap::ui {

void addLanguageMenu(QMenu& menu, SessionOption<QString>& language, const QStringList& codes, const QStringList& names,
                     const QString& fallback, QWidget& dialogParent)
{
  auto* group = new QActionGroup(&menu);
  const QString current = language.get().isEmpty() ? fallback : language.get();
  for (int i = 0; i < codes.size() && i < names.size(); ++i) {
    QAction* action = menu.addAction(names[i]);
    action->setCheckable(true);
    action->setChecked(codes[i] == current);
    group->addAction(action);
    QObject::connect(action, &QAction::triggered, action, [&language, &dialogParent, code = codes[i]] {
      language = code;
      sayLanguageIsUsedFromTheNextStart(dialogParent);
    });
  }
}

} // namespace mocap::ui
