// Defaults that never invent or mislead (issue 13 §3), on the sample take under Xvfb: one set of
// head reference markers per take, owned by the document and used by every panel; Export
// Animation exports the whole take unless told otherwise and asks before replacing files; an
// operation with nothing to do leaves the take, its history and its modified mark alone.
#include "job_waits.h"
#include "../core/test_support.h"

#include "commands/remove_markers_command.h"
#include "commands/rename_marker_command.h"
#include "dialogs/export_dialog.h"
#include "dialogs/reference_markers_dialog.h"
#include "document/layout_plan_model.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "main_window.h"
#include "sample_window.h"
#include "panels/cleaning_panel.h"
#include "panels/head_stabilization_step.h"
#include "panels/layout_planning_panel.h"
#include "panels/reference_markers_row.h"

#include "mocap/base/file_io.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDockWidget>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <functional>

namespace mocap {
namespace {

using studio::MainWindow;
using ui::TakeDocument;

const std::vector<std::string> kRoots = {"root-1", "root-2", "root-3", "root-4", "root-5", "root-6"};

/// Runs `answer` on the modal widget that the next blocking call opens (polled, so it also finds
/// a message box opened from inside another modal dialog).
void whenModal(std::function<void(QWidget*)> answer)
{
  auto* timer = new QTimer;
  timer->setInterval(20);
  QObject::connect(timer, &QTimer::timeout, [timer, answer = std::move(answer)] {
    if (QWidget* modal = QApplication::activeModalWidget()) {
      timer->stop();
      timer->deleteLater();
      answer(modal);
    }
  });
  timer->start();
}

QAction* actionNamed(const QWidget& window, const QString& text)
{
  for (QAction* action : window.findChildren<QAction*>())
    if (action->text() == text || action->objectName() == text)
      return action;
  return nullptr;
}

using ReferenceMarkers = test::SampleWindowTest;

TEST_F(ReferenceMarkers, TheSampleOpensWithItsRootMarkersAsTheReference)
{
  EXPECT_EQ(doc().referenceLabels(), kRoots);
  EXPECT_EQ(doc().referenceMarkers().size(), 6u);
  EXPECT_FALSE(doc().isModified()) << "a guess is not an edit";
  EXPECT_EQ(doc().undoStack()->count(), 0);
  // Every panel shows that one set.
  for (const ui::ReferenceMarkersRow* row : window->findChildren<ui::ReferenceMarkersRow*>())
    EXPECT_TRUE(row->text().startsWith(QStringLiteral("root-1, root-2"))) << row->text().toStdString();
  EXPECT_GE(window->findChildren<ui::ReferenceMarkersRow*>().size(), 3u) << "layout, face mesh, stabilize head";
  // A new take gets its own guess.
  doc().setTake(Take({"a", "b", "c"}, 5, 100.0));
  EXPECT_TRUE(doc().referenceMarkers().empty());
}

TEST_F(ReferenceMarkers, LayoutPlanningStabilizesWithThemAndLeavesThemOut)
{
  window->findChild<QDockWidget*>(QStringLiteral("layoutPlanningDock"))->raise();
  ui::LayoutPlanningPanel* panel = window->layoutPlanningPanel();
  ui::LayoutPlanParameters quick;  // nothing about reference markers: the document's set is used
  quick.restarts = 5;
  quick.minK = 3;
  quick.maxK = 12;
  quick.seed = 7;
  panel->setParameters(quick);
  ASSERT_EQ(panel->run(), QString());
  ASSERT_TRUE(test::waitForJob(panel->jobs()));
  ASSERT_NE(window->session().layoutPlan().result(), nullptr) << panel->statusText().toStdString();
  const ui::LayoutPlanResult& result = *window->session().layoutPlan().result();
  EXPECT_TRUE(result.frames.stabilized);
  EXPECT_EQ(result.stabilizeLabels, kRoots);
  EXPECT_EQ(result.frames.markerCount(), 31) << "38 less the 6 reference markers and Unlabeled1";
  for (const std::string& label : result.frames.labels)
    EXPECT_NE(label.rfind("root-", 0), 0u) << label << " was planned as a face marker";
  EXPECT_TRUE(panel->statusText().contains(QStringLiteral("head motion removed"))) << panel->statusText().toStdString();
}

TEST_F(ReferenceMarkers, MarkerEditsKeepTheSetOnTheSameLabels)
{
  QUndoStack* undo = doc().undoStack();
  // Removing a marker before the set's markers shifts their indices, not their labels.
  const Eigen::Index first = 0;
  ASSERT_EQ(doc().take().label(first), "root-1");
  undo->push(new ui::RemoveMarkersCommand(doc(), {first}));
  EXPECT_EQ(doc().referenceLabels(), std::vector<std::string>(kRoots.begin() + 1, kRoots.end()));
  undo->undo();
  EXPECT_EQ(doc().referenceLabels(), kRoots) << "undo brings the removed reference marker back into the set";
  const Eigen::Index other = *doc().take().markerIndex("section7-1");
  undo->push(new ui::RemoveMarkersCommand(doc(), {other}));
  EXPECT_EQ(doc().referenceLabels(), kRoots);
  undo->undo();
  // Renaming keeps the marker in the set under its new name.
  undo->push(new ui::RenameMarkerCommand(doc(), *doc().take().markerIndex("root-3"), "head-3"));
  std::vector<std::string> renamed = kRoots;
  renamed[2] = "head-3";
  EXPECT_EQ(doc().referenceLabels(), renamed);
  undo->undo();
  EXPECT_EQ(doc().referenceLabels(), kRoots);
}

TEST_F(ReferenceMarkers, EditingTheSetInTheDialogIsOneUndoStep)
{
  QAction* edit = actionNamed(*window, QStringLiteral("referenceMarkersAction"));
  ASSERT_NE(edit, nullptr);
  EXPECT_EQ(edit->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
  int listed = 0;
  whenModal([&listed](QWidget* modal) {
    auto* dialog = qobject_cast<ui::ReferenceMarkersDialog*>(modal);
    if (!dialog) {
      ADD_FAILURE() << "not the reference markers dialog";
      modal->close();
      return;
    }
    listed = dialog->list()->count();
    for (int row = 0; row < dialog->list()->count(); ++row)
      if (dialog->list()->item(row)->text() == QStringLiteral("root-6"))
        dialog->list()->item(row)->setCheckState(Qt::Unchecked);
    dialog->accept();
  });
  edit->trigger();
  EXPECT_EQ(listed, 38);
  EXPECT_EQ(doc().referenceLabels(), std::vector<std::string>(kRoots.begin(), kRoots.end() - 1));
  EXPECT_EQ(doc().undoStack()->count(), 1);
  EXPECT_TRUE(doc().isModified());
  doc().undoStack()->undo();
  EXPECT_EQ(doc().referenceLabels(), kRoots);
  EXPECT_FALSE(doc().isModified());

  // OK with the set as it is pushes nothing; one or two markers cannot be accepted.
  doc().undoStack()->clear();
  bool okEnabledForTwo = true;
  whenModal([&okEnabledForTwo](QWidget* modal) {
    auto* dialog = qobject_cast<ui::ReferenceMarkersDialog*>(modal);
    if (!dialog) {
      ADD_FAILURE() << "not the reference markers dialog";
      modal->close();
      return;
    }
    const std::vector<Eigen::Index> all = dialog->chosen();
    dialog->setChosen({all[0], all[1]});
    okEnabledForTwo = false;
    for (QPushButton* button : dialog->findChildren<QPushButton*>())
      if (button->text() == QStringLiteral("&OK") || button->text() == QStringLiteral("OK"))
        okEnabledForTwo = button->isEnabled();
    dialog->setChosen(all);
    dialog->accept();
  });
  edit->trigger();
  EXPECT_FALSE(okEnabledForTwo);
  EXPECT_EQ(doc().undoStack()->count(), 0);
  EXPECT_FALSE(doc().isModified());
}

TEST_F(ReferenceMarkers, HeadStabilizationCoversEveryMarkerAndFrameEvenWithSelectedOnly)
{
  ui::CleaningPanel* panel = window->cleaningPanel();
  for (QCheckBox* box : panel->findChildren<QCheckBox*>())
    if (box->text() == QStringLiteral("Selected markers only") || box->objectName() == QStringLiteral("rangeOnly"))
      box->setChecked(true);
  window->selectLabels({QStringLiteral("section7-1"), QStringLiteral("section7-2")});
  doc().setRange(100, 199);
  auto* step = panel->step<ui::HeadStabilizationStep>();
  ASSERT_NE(step, nullptr);
  panel->setCurrentStep(step);
  test::waitForPreview(*panel);
  const auto& patches = panel->lastResult().patches;
  ASSERT_EQ(static_cast<Eigen::Index>(patches.size()), doc().take().markerCount())
      << panel->lastResult().summary.toStdString();
  for (const SamplePatch& patch : patches)
    EXPECT_EQ(static_cast<Eigen::Index>(patch.frames.size()), doc().take().frameCount());
  ASSERT_GT(panel->apply(), 0);
  EXPECT_EQ(doc().undoStack()->count(), 1);
}

TEST_F(ReferenceMarkers, ExportAnimationDefaultsToTheWholeTakeAfterAShiftDrag)
{
  const Take& take = doc().take();
  doc().setRange(1000, 1071);  // a Shift-drag on the curves, long forgotten
  ui::ExportDialog dialog(doc());
  EXPECT_EQ(dialog.rangeChoice(), ui::ExportDialog::RangeChoice::WholeTake);
  EXPECT_EQ(dialog.firstFrame(), take.firstFrame());
  EXPECT_EQ(dialog.lastFrame(), take.firstFrame() + take.frameCount() - 1);
  dialog.setRangeChoice(ui::ExportDialog::RangeChoice::SelectedRange);  // offered, not assumed
  EXPECT_EQ(dialog.firstFrame(), take.firstFrame() + 1000);
  EXPECT_EQ(dialog.lastFrame(), take.firstFrame() + 1071);
  dialog.setFrameRange(take.firstFrame() + 5, take.firstFrame() + 9);
  EXPECT_EQ(dialog.rangeChoice(), ui::ExportDialog::RangeChoice::Custom);
}

TEST_F(ReferenceMarkers, ExportAnimationAsksBeforeReplacingAFile)
{
  test::TempDir dir;
  const auto bvh = dir.file("take.bvh");
  writeFileAtomically(bvh, "an older export\n");
  ui::ExportDialog dialog(doc());
  dialog.setFormat(ui::AnimationFormat::Bvh);
  dialog.setOutputPath(QString::fromStdString(bvh.string()));
  dialog.setRangeChoice(ui::ExportDialog::RangeChoice::Custom);
  dialog.setFrameRange(doc().take().firstFrame(), doc().take().firstFrame() + 9);
  QString question;
  whenModal([&question](QWidget* modal) {
    auto* box = qobject_cast<QMessageBox*>(modal);
    if (!box) {
      ADD_FAILURE() << "no question";
      modal->close();
      return;
    }
    question = box->text();
    box->button(QMessageBox::No)->click();
  });
  EXPECT_FALSE(dialog.startExport());
  EXPECT_TRUE(question.contains(QStringLiteral("take.bvh"))) << question.toStdString();
  EXPECT_EQ(readFileBytes(bvh), "an older export\n") << "No keeps the file";
  whenModal([](QWidget* modal) { qobject_cast<QMessageBox*>(modal)->button(QMessageBox::Yes)->click(); });
  ASSERT_TRUE(dialog.startExport()) << dialog.statusText().toStdString();
  ASSERT_TRUE(test::waitForJob(dialog.jobs()));
  EXPECT_NE(readFileBytes(bvh).find("HIERARCHY"), std::string::npos) << "Yes replaces it";
}

TEST_F(ReferenceMarkers, TrackAndLabelWithNothingToLabelChangesNothing)
{
  QAction* track = actionNamed(*window, QStringLiteral("&Track and Label"));
  ASSERT_NE(track, nullptr);
  const Eigen::Index markers = doc().take().markerCount();
  track->trigger();
  EXPECT_EQ(doc().take().markerCount(), markers);
  EXPECT_EQ(doc().undoStack()->count(), 0);
  EXPECT_FALSE(doc().isModified());
  EXPECT_TRUE(window->statusBar()->currentMessage().startsWith(QStringLiteral("Nothing to label")))
      << window->statusBar()->currentMessage().toStdString();
}

// One head motion per state of the take, shared by the 3D view and the face mesh: estimated once,
// estimated again after an edit of a reference marker (and after its undo), never cached when refused.
TEST_F(ReferenceMarkers, TheDocumentEstimatesTheHeadMotionOncePerStateOfTheTake)
{
  const std::vector<Eigen::Index> reference = doc().referenceMarkers();
  const auto first = doc().headMotion(reference);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(doc().headMotion(reference), first) << "a second ask is answered from the cache";

  const Eigen::Index root = reference.front();
  doc().setSelection({root});
  doc().setRange(100, 400);
  QAction* remove = actionNamed(*window, QStringLiteral("&Delete Range"));
  ASSERT_NE(remove, nullptr);
  remove->trigger();  // a gap in a reference marker moves the poses estimated there
  ASSERT_EQ(doc().undoStack()->count(), 1);
  const auto edited = doc().headMotion(reference);
  ASSERT_NE(edited, first);
  EXPECT_FALSE(edited->poses[250].isApprox(first->poses[250], 1e-12) && edited->known == first->known)
      << "the estimate follows the edit";
  doc().undoStack()->undo();
  const auto undone = doc().headMotion(reference);
  ASSERT_NE(undone, edited);
  EXPECT_TRUE(undone->poses[250].isApprox(first->poses[250], 1e-12));

  const std::vector<Eigen::Index> two(reference.begin(), reference.begin() + 2);
  EXPECT_THROW((void)doc().headMotion(two), std::exception) << "two markers cannot carry a pose";
  EXPECT_THROW((void)doc().headMotion(two), std::exception) << "and the refusal is not cached as a motion";
}

TEST_F(ReferenceMarkers, DeleteRangeOnAGapPushesNothing)
{
  const Eigen::Index marker = *doc().take().markerIndex("section7-1");
  doc().setSelection({marker});
  doc().setRange(10, 20);
  QAction* remove = actionNamed(*window, QStringLiteral("&Delete Range"));
  ASSERT_NE(remove, nullptr);
  remove->trigger();
  ASSERT_EQ(doc().undoStack()->count(), 1);
  remove->trigger();  // the range is a gap now
  EXPECT_EQ(doc().undoStack()->count(), 1);
  EXPECT_TRUE(window->statusBar()->currentMessage().startsWith(QStringLiteral("Nothing to delete")))
      << window->statusBar()->currentMessage().toStdString();
}

} // namespace
} // namespace mocap
