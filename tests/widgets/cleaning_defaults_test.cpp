// The cleaning panel's defaults on the real sample take: the Gaps step leaves long and edge gaps
// open and lists them; bad-point flags are the document's, on every tab, until detected again.
#include "job_waits.h"
#include "../core/test_support.h"

#include "document/take_document.h"
#include "main_window.h"
#include "sample_window.h"
#include "models/marker_table_model.h"
#include "panels/cleaning_panel.h"
#include "panels/gap_fill_step.h"
#include "panels/spike_step.h"

#include "mocap/cleaning/fill/gap_fill.h"
#include "mocap/model/gaps.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QListWidget>
#include <QSpinBox>
#include <QSettings>
#include <QTableView>
#include <QStatusBar>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <algorithm>

namespace mocap {
namespace {

using studio::MainWindow;
using ui::TakeDocument;

class CleaningDefaults : public ::testing::Test
{
protected:
  void SetUp() override
  {
    window = test::openSampleWindow(1280, 800);
    ASSERT_NE(window, nullptr);
  }

  /// The marker table's bad-points column summed over all rows.
  int badPointsInTable() const
  {
    QAbstractItemModel* model = window->markerTable()->model();
    int sum = 0;
    for (int row = 0; row < model->rowCount(); ++row)
      sum += model->index(row, ui::MarkerTableModel::BadPointsColumn).data().toInt();
    return sum;
  }

  std::unique_ptr<MainWindow> window;
};

TEST_F(CleaningDefaults, GapsStepLeavesUnlabeled1sLongGapsOpenAndListsThem)
{
  TakeDocument& doc = window->document();
  const Take before = doc.take();
  const Eigen::Index stray = *before.markerIndex("Unlabeled1");
  std::vector<Gap> longGaps;
  for (const Gap& gap : findGaps(before.valid().col(stray), stray))
    if (gap.length == 703 || gap.length == 865)
      longGaps.push_back(gap);
  ASSERT_EQ(longGaps.size(), 2u) << "the sample take's two long gaps of Unlabeled1";

  ui::CleaningPanel* panel = window->cleaningPanel();
  auto* step = panel->step<ui::GapFillStep>();
  ASSERT_NE(step, nullptr);
  EXPECT_DOUBLE_EQ(step->maxGapSeconds(), 0.5);
  auto* frames = step->findChild<QSpinBox*>(QStringLiteral("maxGapFrames"));
  ASSERT_NE(frames, nullptr);
  EXPECT_EQ(frames->value(), 50) << "0.5 s at the take's 100 Hz";
  panel->setCurrentStep(step);
  test::waitForPreview(*panel);
  const ui::StepResult& preview = panel->lastResult();
  for (const SamplePatch& patch : preview.patches)
    EXPECT_NE(patch.marker, stray) << "nothing invented for Unlabeled1";
  EXPECT_TRUE(preview.summary.contains(QStringLiteral("left open"))) << preview.summary.toStdString();
  auto* open = step->findChild<QListWidget*>(QStringLiteral("openGaps"));
  ASSERT_NE(open, nullptr);
  int strayRows = 0;
  for (int i = 0; i < open->count(); ++i)
    strayRows += open->item(i)->text().startsWith(QStringLiteral("Unlabeled1")) ? 1 : 0;
  EXPECT_GE(strayRows, 2) << "its gaps are listed with why";

  // The summary counts what the core leaves open, cause by cause.
  const FillResult core = fillGaps(before, FillOptions{});
  int filled = 0, open_ = 0;
  for (const GapFillReport& report : core.gaps)
    (report.filled ? filled : open_) += 1;
  EXPECT_TRUE(preview.summary.startsWith(QStringLiteral("%1 gap").arg(filled))) << preview.summary.toStdString();
  EXPECT_TRUE(preview.summary.contains(QStringLiteral("%1 left open").arg(open_))) << preview.summary.toStdString();
  EXPECT_EQ(open->count(), open_);

  ASSERT_GT(panel->apply(), 0);
  for (const Gap& gap : longGaps)
    EXPECT_FALSE(doc.take().valid().col(stray).segment(gap.firstFrame, gap.length).any());
  // After Apply the summary still counts the open gaps, and no filled one is left.
  test::waitForPreview(*panel);
  EXPECT_TRUE(panel->lastResult().summary.startsWith(QStringLiteral("No gap filled")))
      << panel->lastResult().summary.toStdString();
  EXPECT_TRUE(panel->lastResult().summary.contains(QStringLiteral("%1 left open").arg(open_)));
}

TEST_F(CleaningDefaults, SelectedMarkersOnlyCountsAndFillsTheSelection)
{
  TakeDocument& doc = window->document();
  const Eigen::Index stray = *doc.take().markerIndex("Unlabeled1");
  ui::CleaningPanel* panel = window->cleaningPanel();
  auto* step = panel->step<ui::GapFillStep>();
  panel->setCurrentStep(step);
  QCheckBox* selectedOnly = nullptr;
  for (QCheckBox* box : panel->findChildren<QCheckBox*>())
    if (box->text() == QStringLiteral("Selected markers only"))
      selectedOnly = box;
  ASSERT_NE(selectedOnly, nullptr);
  selectedOnly->setChecked(true);
  doc.setSelection({stray});
  step->setMaxGapSeconds(0.0);  // unlimited: only the edges and the choice of marker remain
  auto* method = step->findChild<QComboBox*>();
  ASSERT_NE(method, nullptr);
  method->setCurrentIndex(method->findData(static_cast<int>(FillMethod::Linear)));
  test::waitForPreview(*panel);
  const ui::StepResult& preview = panel->lastResult();
  // Selected, the rarely seen marker is filled (between its samples), and only it.
  ASSERT_FALSE(preview.patches.empty()) << preview.summary.toStdString();
  for (const SamplePatch& patch : preview.patches)
    EXPECT_EQ(patch.marker, stray);
  auto* open = step->findChild<QListWidget*>(QStringLiteral("openGaps"));
  for (int i = 0; i < open->count(); ++i)
    EXPECT_TRUE(open->item(i)->text().startsWith(QStringLiteral("Unlabeled1"))) << open->item(i)->text().toStdString();
  EXPECT_TRUE(preview.summary.startsWith(QStringLiteral("%1 gap").arg(preview.patches.size())))
      << preview.summary.toStdString();
}

TEST_F(CleaningDefaults, BadPointFlagsStayOnEveryTabAndCtrlPageDownReachesThem)
{
  TakeDocument& doc = window->document();
  ui::CleaningPanel* panel = window->cleaningPanel();
  panel->setCurrentStep(panel->step<ui::SpikeStep>());
  test::waitForPreview(*panel);
  const auto flags = doc.flags();
  ASSERT_FALSE(flags.empty());
  const int counted = badPointsInTable();
  EXPECT_EQ(counted, static_cast<int>(flags.size()));

  panel->setCurrentStep(panel->step<ui::GapFillStep>());
  test::waitForPreview(*panel);
  EXPECT_EQ(doc.flags(), flags) << "switching tabs keeps the last detection";
  EXPECT_EQ(badPointsInTable(), counted);

  doc.setSelection({});
  doc.setCurrentFrame(0);
  Eigen::Index next = doc.take().frameCount();
  for (const auto& [marker, frame] : flags)
    if (frame > 0)
      next = std::min(next, frame);
  QTest::keyClick(window.get(), Qt::Key_PageDown, Qt::ControlModifier);
  EXPECT_EQ(doc.currentFrame(), next) << "Ctrl+PgDn from the Gaps tab";
  // The status bar names the flagged marker and why it stands out.
  Eigen::Index flagged = -1;
  for (const auto& [marker, frame] : flags)
    if (frame == next && flagged < 0)
      flagged = marker;
  const QString said = window->statusBar()->currentMessage();
  EXPECT_TRUE(said.startsWith(QStringLiteral("Bad point at frame %1: ").arg(doc.take().firstFrame() + next)))
      << said.toStdString();
  EXPECT_TRUE(said.contains(QString::fromStdString(doc.take().label(flagged)))) << said.toStdString();
  EXPECT_TRUE(said.contains(QStringLiteral("off the mid-point of its neighbours"))) << said.toStdString();

  // A different take clears them.
  ASSERT_EQ(window->openFile(QString::fromStdString(test::sampleTake().string()), true), QString());
  EXPECT_TRUE(doc.flags().empty());
}

TEST_F(CleaningDefaults, RepairingBadPointsSettlesThem)
{
  TakeDocument& doc = window->document();
  ui::CleaningPanel* panel = window->cleaningPanel();
  auto* step = panel->step<ui::SpikeStep>();
  panel->setCurrentStep(step);
  auto* settle = step->findChild<QCheckBox*>(QStringLiteral("settle"));
  ASSERT_NE(settle, nullptr);
  settle->setChecked(true);  // look again until nothing new
  test::waitForPreview(*panel);
  const std::size_t found = doc.flags().size();
  ASSERT_GT(found, 100u);
  ASSERT_GT(panel->apply(), 0);
  test::waitForPreview(*panel);  // detects again on the repaired take
  EXPECT_LE(doc.flags().size(), found / 50) << found << " then " << doc.flags().size();  // 213 then 4
  EXPECT_EQ(badPointsInTable(), static_cast<int>(doc.flags().size()));
}

// With one pass (the default), detecting again after a repair flags parts of long glitches beside
// the repaired samples; the summary says so, why, and what to do, instead of leaving it a mystery.
TEST_F(CleaningDefaults, DetectingAgainAfterARepairExplainsTheFlagsBesideIt)
{
  TakeDocument& doc = window->document();
  ui::CleaningPanel* panel = window->cleaningPanel();
  auto* step = panel->step<ui::SpikeStep>();
  panel->setCurrentStep(step);
  test::waitForPreview(*panel);
  EXPECT_FALSE(panel->lastResult().summary.contains(QStringLiteral("beside")));
  ASSERT_GT(panel->apply(), 0);
  test::waitForPreview(*panel);
  ASSERT_FALSE(doc.flags().empty());
  const QString summary = panel->lastResult().summary;
  EXPECT_TRUE(summary.contains(QStringLiteral("beside samples just repaired")) &&
              summary.contains(QStringLiteral("Look again until nothing new")))
      << summary.toStdString();
  // Undone, the repair no longer explains anything.
  doc.undoStack()->undo();
  test::waitForPreview(*panel);
  EXPECT_FALSE(panel->lastResult().summary.contains(QStringLiteral("beside"))) << panel->lastResult().summary.toStdString();
}

// After Apply the panel says what was done, counted from what was applied, not what the next pass
// would do; a changed setting or an undo hands the status back to the preview.
TEST_F(CleaningDefaults, AfterApplyTheStatusSaysWhatWasDone)
{
  TakeDocument& doc = window->document();
  ui::CleaningPanel* panel = window->cleaningPanel();
  auto* gaps = panel->step<ui::GapFillStep>();
  panel->setCurrentStep(gaps);
  test::waitForPreview(*panel);
  int filled = 0, samples = 0;
  for (const SamplePatch& patch : panel->lastResult().patches) {
    ++filled;
    samples += static_cast<int>(patch.size());
  }
  const auto open = static_cast<int>(panel->lastResult().notes.size());
  ASSERT_GT(filled, 1);
  ASSERT_GT(open, 3);
  const QString firstOpen = panel->lastResult().notes.front().text;
  ASSERT_EQ(panel->apply(), samples);
  test::waitForPreview(*panel);  // the next pass: nothing left to fill
  const QString expected = QStringLiteral("Applied: %1 gaps filled, %2 samples; %3 left open: %4")
                               .arg(filled)
                               .arg(samples)
                               .arg(open)
                               .arg(firstOpen);
  EXPECT_TRUE(panel->statusText().startsWith(expected)) << panel->statusText().toStdString() << "\n" << expected.toStdString();
  EXPECT_FALSE(panel->statusText().contains(QStringLiteral("No gap filled"))) << panel->statusText().toStdString();
  // A changed setting: the preview speaks again.
  gaps->setMaxGapSeconds(0.3);
  test::waitForPreview(*panel);
  EXPECT_FALSE(panel->statusText().startsWith(QStringLiteral("Applied"))) << panel->statusText().toStdString();

  // Bad points: samples repaired on markers, from the patches pushed.
  panel->setCurrentStep(panel->step<ui::SpikeStep>());
  test::waitForPreview(*panel);
  std::vector<Eigen::Index> markers;
  for (const SamplePatch& patch : panel->lastResult().patches)
    markers.push_back(patch.marker);
  std::sort(markers.begin(), markers.end());
  markers.erase(std::unique(markers.begin(), markers.end()), markers.end());
  const int repaired = panel->apply();
  ASSERT_GT(repaired, 1);
  test::waitForPreview(*panel);
  EXPECT_TRUE(panel->statusText().startsWith(
      QStringLiteral("Applied: %1 samples repaired on %2 markers").arg(repaired).arg(markers.size())))
      << panel->statusText().toStdString();
  doc.undoStack()->undo();  // the take changed: the preview speaks again
  test::waitForPreview(*panel);
  EXPECT_FALSE(panel->statusText().startsWith(QStringLiteral("Applied"))) << panel->statusText().toStdString();
}

// Every method of every step says what it does in a tooltip, and none is named by equation numbers.
TEST_F(CleaningDefaults, EveryMethodHasATooltipAndNoNameSaysEqs)
{
  ui::CleaningPanel* panel = window->cleaningPanel();
  int methods = 0;
  for (ui::CleaningStep* step : panel->steps())
    for (QComboBox* combo : step->findChildren<QComboBox*>()) {
      for (int i = 0; i < combo->count(); ++i) {
        ++methods;
        const QString tip = combo->itemData(i, Qt::ToolTipRole).toString();
        EXPECT_FALSE(tip.isEmpty()) << step->title().toStdString() << ": " << combo->itemText(i).toStdString();
        EXPECT_FALSE(combo->itemText(i).contains(QStringLiteral("eqs"), Qt::CaseInsensitive))
            << combo->itemText(i).toStdString();
        EXPECT_FALSE(tip.contains(QStringLiteral("eqs"), Qt::CaseInsensitive)) << tip.toStdString();
      }
      EXPECT_EQ(combo->toolTip(), combo->currentData(Qt::ToolTipRole).toString()) << "the chosen method's tip";
    }
  EXPECT_EQ(methods, 2 + 9 + 4) << "spike detectors, fill methods, smoothers";
}

} // namespace
} // namespace mocap
