#include "actions/take_units_menu.h"

#include "commands/record_step_command.h"
#include "commands/replace_take_command.h"
#include "document/take_document.h"

#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QMenu>

#include <array>

namespace mocap::ui {

namespace {

/// The take with its positions named in `unit`, as one undoable step with its history entry.
void nameUnits(TakeDocument& document, LengthUnit unit)
{
  const LengthUnit was = document.take().units();
  if (unit == was || !document.hasTake())
    return;
  Take renamed = document.take();
  renamed.setUnits(unit);
  const std::string from(unitName(was)), to(unitName(unit));
  ProcessingStep step = studioStep(document, "name units", {{"from", from}, {"to", to}}, {}, 0, -1, 0);
  document.undoStack()->push(new ReplaceTakeCommand(
      document, std::move(renamed),
      QCoreApplication::translate("TakeUnitsMenu", "Positions Are In %1 (were read as %2)").arg(QString::fromStdString(to), QString::fromStdString(from)),
      std::move(step)));
}

} // namespace

void addTakeUnitsMenu(QMenu& edit, TakeDocument& document)
{
  QMenu* menu = edit.addMenu(QCoreApplication::translate("TakeUnitsMenu", "Positions Are &In"));
  menu->setToolTipsVisible(true);
  auto* group = new QActionGroup(menu);
  const std::array<LengthUnit, 3> units = {LengthUnit::Millimetre, LengthUnit::Centimetre, LengthUnit::Metre};
  for (const LengthUnit unit : units) {
    QAction* action = menu->addAction(QString::fromStdString(std::string(unitName(unit))));
    action->setCheckable(true);
    action->setToolTip(QCoreApplication::translate("TakeUnitsMenu", "The file's numbers are in this unit (nothing is rescaled; undoable)"));
    group->addAction(action);
    QObject::connect(action, &QAction::triggered, menu, [&document, unit] { nameUnits(document, unit); });
  }
  const auto follow = [&document, group, units] {
    const auto actions = group->actions();
    for (std::size_t i = 0; i < units.size(); ++i)
      actions[static_cast<qsizetype>(i)]->setChecked(document.take().units() == units[i]);
    group->setEnabled(document.hasTake());
  };
  QObject::connect(&document, &TakeDocument::takeReset, menu, follow);
  QObject::connect(&document, &TakeDocument::markersChanged, menu, follow);
  follow();
}

} // namespace mocap::ui
