// Edit ▸ Positions Are In (issue 30): a foreign file's unit named in the studio, without a window:
// no number changes, one undoable step in the history, the checked entry follows the take.
#include "../core/test_support.h"

#include "actions/take_units_menu.h"
#include "document/take_document.h"

#include "mocap/io/take_io.h"

#include <QAction>
#include <QMenu>
#include <QUndoStack>

#include <gtest/gtest.h>

namespace mocap {
namespace {

QAction* unitAction(QMenu& edit, const QString& unit)
{
  for (QAction* entry : edit.actions())
    if (QMenu* units = entry->menu())
      for (QAction* action : units->actions())
        if (action->text() == unit)
          return action;
  return nullptr;
}

TEST(TakeUnitsMenu, NamingTheUnitKeepsEveryNumberAndIsOneUndoableStep)
{
  // A real SIMI export in metres whose file names no unit: read as millimetres.
  ui::TakeDocument document;
  document.setTake(readTake(test::dataFile("c3d/sample16/basketball.c3d")));
  const Take before = document.take();
  ASSERT_EQ(before.units(), LengthUnit::Millimetre);
  QMenu edit;
  ui::addTakeUnitsMenu(edit, document);
  QAction* mm = unitAction(edit, QStringLiteral("mm"));
  QAction* m = unitAction(edit, QStringLiteral("m"));
  ASSERT_NE(mm, nullptr);
  ASSERT_NE(m, nullptr);
  EXPECT_TRUE(mm->isChecked());

  m->trigger();
  EXPECT_EQ(document.take().units(), LengthUnit::Metre);
  EXPECT_TRUE(m->isChecked());
  EXPECT_FALSE(mm->isChecked());
  for (Eigen::Index marker = 0; marker < before.markerCount(); ++marker)
    ASSERT_EQ(document.take().trajectory(marker), before.trajectory(marker)) << "nothing rescaled";
  ASSERT_EQ(document.take().history().size(), before.history().size() + 1);
  const ProcessingStep& step = document.take().history().back();
  EXPECT_EQ(step.operation, "name units");
  EXPECT_EQ(step.parameters, (std::vector<std::pair<std::string, std::string>>{{"from", "mm"}, {"to", "m"}}));
  EXPECT_EQ(document.undoStack()->count(), 1);
  m->trigger();  // the unit it already is: nothing to do
  EXPECT_EQ(document.undoStack()->count(), 1);

  document.undoStack()->undo();
  EXPECT_EQ(document.take().units(), LengthUnit::Millimetre);
  EXPECT_EQ(document.take().history().size(), before.history().size());
  EXPECT_TRUE(mm->isChecked());
}

} // namespace
} // namespace mocap
