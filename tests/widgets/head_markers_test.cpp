// Head reference markers belong to the take (issue 30, "Silent context"): the chosen set is saved
// with it (C3D PROCESSING group, TRC sidecar) and comes back on reopen and from a crash recovery
// file; a take with no saved set and no root…/head… labels is not guessed silently: a bar proposes
// the most rigid cluster and asks once, and Accept is one undoable edit.
#include "sample_files.h"
#include "../core/test_support.h"

#include "document/autosave.h"
#include "document/take_document.h"
#include "main_window.h"
#include "actions/reference_marker_actions.h"
#include "panels/head_markers_proposal_bar.h"
#include "panels/reference_markers_row.h"
#include "sample_window.h"

#include "mocap/io/take_io.h"
#include "mocap/model/provenance.h"

#include <QPushButton>
#include <QSettings>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

namespace mocap {
namespace {

using test::qpath;

using ui::TakeDocument;

const std::vector<std::string> kChosen = {"root-1", "root-2", "root-3", "root-4"};

class HeadMarkers : public test::SampleWindowTest
{
protected:
  /// Makes the first four roots the set, as the Reference Markers dialog's OK does.
  void chooseFourRoots()
  {
    std::vector<Eigen::Index> markers;
    for (const std::string& label : kChosen)
      markers.push_back(*doc().take().markerIndex(label));
    ASSERT_TRUE(window->referenceMarkerActions()->change(markers));
  }
};

TEST_F(HeadMarkers, TheChosenSetIsSavedWithTheTakeAndRestoredOnReopen)
{
  EXPECT_TRUE(headMarkers(doc().take()).empty()) << "root… labels name the set; nothing chosen yet";
  chooseFourRoots();
  EXPECT_EQ(headMarkers(doc().take()), kChosen) << "the take holds the chosen set";
  // Undo of a choice puts back the set as it was: named by labels, not saved.
  doc().undoStack()->undo();
  EXPECT_TRUE(headMarkers(doc().take()).empty());
  EXPECT_EQ(doc().referenceLabels().size(), 6u);
  doc().undoStack()->redo();
  test::TempDir dir;
  for (const char* name : {"take.c3d", "take.trc"}) {
    const QString path = qpath(dir.file(name));
    ASSERT_EQ(doc().save(path), QString());
    EXPECT_EQ(headMarkers(readTake(path.toStdString())), kChosen) << name;
    ASSERT_EQ(window->openFile(path, true), QString());
    EXPECT_EQ(doc().referenceLabels(), kChosen) << name << ": not the six root… markers of the labels";
    EXPECT_TRUE(doc().referenceMarkersSaved());
    for (const ui::ReferenceMarkersRow* row : window->findChildren<ui::ReferenceMarkersRow*>())
      EXPECT_TRUE(row->text().endsWith(QStringLiteral("(4)"))) << row->text().toStdString();
  }
}

TEST_F(HeadMarkers, CrashRecoveryBringsTheChosenSetBack)
{
  test::TempDir dir;
  ui::Autosave autosave(doc(), qpath(dir.path()));
  chooseFourRoots();  // an unsaved edit: autosave writes the take
  ASSERT_EQ(autosave.saveNow(), QString());
  TakeDocument recovered;
  ASSERT_EQ(recovered.open(autosave.recoveryPath()), QString());
  EXPECT_EQ(recovered.referenceLabels(), kChosen);
}

TEST_F(HeadMarkers, ATakeWithoutHeadLabelsAsksOnceAndAcceptSetsThem)
{
  ui::HeadMarkersProposalBar* bar = window->headMarkersBar();
  ASSERT_NE(bar, nullptr);
  EXPECT_FALSE(bar->isVisibleTo(window.get())) << "the sample names its head markers: nothing to ask";
  // The sample with its root… markers renamed: nothing names the head markers any more.
  Take take = doc().take();
  std::vector<std::string> roots;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    if (take.label(m).rfind("root-", 0) == 0) {
      take.setLabel(m, "marker" + std::to_string(m));
      roots.push_back(take.label(m));
    }
  doc().setTake(std::move(take));
  EXPECT_TRUE(doc().referenceMarkers().empty()) << "nothing is guessed silently";
  const std::vector<Eigen::Index> proposed = doc().proposedReferenceMarkers();
  ASSERT_GE(proposed.size(), 3u);
  ASSERT_TRUE(bar->isVisibleTo(window.get()));
  EXPECT_TRUE(bar->text().startsWith(QStringLiteral("Head markers guessed: marker"))) << bar->text().toStdString();
  for (const Eigen::Index m : proposed) {
    EXPECT_TRUE(bar->text().contains(QString::fromStdString(doc().take().label(m)))) << doc().take().label(m);
    EXPECT_NE(std::find(roots.begin(), roots.end(), doc().take().label(m)), roots.end()) << "a head marker";
  }
  EXPECT_EQ(doc().undoStack()->count(), 0);

  auto* accept = bar->findChild<QPushButton*>(QStringLiteral("acceptHeadMarkers"));
  ASSERT_NE(accept, nullptr);
  QTest::mouseClick(accept, Qt::LeftButton);
  EXPECT_EQ(doc().referenceMarkers(), proposed);
  EXPECT_EQ(headMarkers(doc().take()), doc().referenceLabels()) << "saved with the take";
  EXPECT_EQ(doc().undoStack()->count(), 1);
  EXPECT_FALSE(bar->isVisibleTo(window.get())) << "asked once";
  doc().undoStack()->undo();
  EXPECT_TRUE(doc().referenceMarkers().empty());
  EXPECT_TRUE(headMarkers(doc().take()).empty());
  EXPECT_FALSE(bar->isVisibleTo(window.get())) << "the answer stands for this take";
}

} // namespace
} // namespace mocap
