// The Gaps dock and the timeline's gap marks on the real sample take, through the studio window.
#include "job_waits.h"
#include "../core/test_support.h"

#include "commands/apply_patches_command.h"
#include "document/take_document.h"
#include "main_window.h"
#include "sample_window.h"
#include "models/gap_table_model.h"
#include "panels/cleaning_panel.h"
#include "panels/gap_fill_step.h"
#include "panels/gap_list_panel.h"
#include "views/curve_view.h"
#include "views/timeline_widget.h"

#include "mocap/cleaning/fill/gap_fill.h"
#include "mocap/model/gaps.h"
#include "mocap/model/sample_patch.h"

#include <QElapsedTimer>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QCheckBox>
#include <QDockWidget>
#include <QScrollBar>
#include <QSettings>
#include <QSortFilterProxyModel>
#include <QStatusBar>
#include <QTableView>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <cstring>
#include <iostream>
#include <limits>
#include <tuple>

namespace mocap {
namespace {

using studio::MainWindow;
using ui::GapTableModel;
using ui::TakeDocument;

/// True when the two takes hold the same samples bit for bit.
bool sameSamples(const Take& a, const Take& b)
{
  if (a.frameCount() != b.frameCount() || a.markerCount() != b.markerCount())
    return false;
  const auto n = static_cast<std::size_t>(a.frameCount() * a.markerCount());
  return std::memcmp(a.positionData(), b.positionData(), n * 3 * sizeof(double)) == 0 &&
         (a.valid() == b.valid()).all() &&
         std::memcmp(a.residuals().data(), b.residuals().data(), n * sizeof(double)) == 0 &&
         (a.states() == b.states()).all();
}

class GapList : public ::testing::Test
{
protected:
  void SetUp() override
  {
    window = test::openSampleWindow(1280, 800);
    ASSERT_NE(window, nullptr);
    panel = window->gapListPanel();
    ASSERT_NE(panel, nullptr);
    model = panel->model();
  }

  TakeDocument& doc() { return window->document(); }

  /// The model row of the gap of `label` that starts at file frame `fileFrame`.
  int rowOf(const std::string& label, std::int64_t fileFrame)
  {
    const Take& take = doc().take();
    return model->rowOf(*take.markerIndex(label), static_cast<Eigen::Index>(fileFrame - take.firstFrame()));
  }

  QString cell(int row, int column) { return model->index(row, column).data().toString(); }

  std::unique_ptr<MainWindow> window;
  ui::GapListPanel* panel = nullptr;
  GapTableModel* model = nullptr;
};

TEST_F(GapList, ShowsExactlyTheGapsCoreFinds)
{
  const Take& take = doc().take();
  const std::vector<Gap> gaps = findGaps(take);
  ASSERT_EQ(model->rowCount(), static_cast<int>(gaps.size()));
  ASSERT_GT(gaps.size(), 20u);
  for (int row = 0; row < model->rowCount(); ++row) {
    const Gap& gap = gaps[static_cast<std::size_t>(row)];
    EXPECT_EQ(model->gapAt(row).marker, gap.marker);
    EXPECT_EQ(model->gapAt(row).firstFrame, gap.firstFrame);
    EXPECT_EQ(model->gapAt(row).length, gap.length);
    EXPECT_EQ(model->stateAt(row), GapTableModel::FillState::Open);
  }
  // section5-1 loses frames 1723–1788 of the file.
  const int row = rowOf("section5-1", 1723);
  ASSERT_GE(row, 0);
  EXPECT_EQ(cell(row, GapTableModel::MarkerColumn), "section5-1");
  EXPECT_EQ(cell(row, GapTableModel::FirstFrameColumn), "1723");
  EXPECT_EQ(cell(row, GapTableModel::LengthColumn), "66");
  EXPECT_EQ(cell(row, GapTableModel::SecondsColumn), "0.66");
  EXPECT_EQ(cell(row, GapTableModel::StateColumn), "over the 0.5 s limit") << "66 frames at 100 Hz";
  EXPECT_EQ(model->refusalAt(row), UnfilledCause::TooLong);
  EXPECT_EQ(cell(row, GapTableModel::MethodColumn), GapTableModel::methodTitle(FillOptions{}.method));
  const int shorter = rowOf("section3-1", 887);  // 33 frames
  EXPECT_EQ(cell(shorter, GapTableModel::StateColumn), "open");
  EXPECT_EQ(model->index(shorter, GapTableModel::StateColumn).data(Qt::CheckStateRole), QVariant())
      << "nothing to allow";
  EXPECT_EQ(model->index(row, GapTableModel::StateColumn).data(Qt::CheckStateRole).toInt(), Qt::Unchecked);
}

TEST_F(GapList, MarkerFramesAndStateFitTheDockOnA1280PixelScreen)
{
  // The studio first opens at 85 % of the screen: 1088×680 on a 1280×800 laptop.
  const auto firstRun = test::openSampleWindow(1088, 680);
  ASSERT_NE(firstRun, nullptr);
  auto* dock = firstRun->findChild<QDockWidget*>(QStringLiteral("gapListDock"));
  ASSERT_NE(dock, nullptr);
  dock->show();
  dock->raise();
  QTest::qWait(50);
  QTableView* view = firstRun->gapListPanel()->view();
  ASSERT_GT(view->model()->rowCount(), 0);
  // What decides a gap (its state and override box) is seen without scrolling sideways; method and
  // seconds may follow.
  const int visible = view->viewport()->width();
  for (const int column : {GapTableModel::MarkerColumn, GapTableModel::FirstFrameColumn, GapTableModel::LengthColumn,
                           GapTableModel::StateColumn})
    EXPECT_LE(view->columnViewportPosition(column) + view->columnWidth(column), visible)
        << model->headerData(column, Qt::Horizontal).toString().toStdString() << " in a viewport " << visible
        << " px wide";
  EXPECT_EQ(view->horizontalScrollBar()->value(), 0);
  // The state column elides: the tooltip holds its whole text (here with what its box overrides).
  const int row = rowOf("section5-1", 1723);
  const QString tip = model->index(row, GapTableModel::StateColumn).data(Qt::ToolTipRole).toString();
  EXPECT_TRUE(tip.contains(cell(row, GapTableModel::StateColumn))) << tip.toStdString();
  EXPECT_TRUE(model->flags(model->index(row, GapTableModel::StateColumn)) & Qt::ItemIsUserCheckable);
}

TEST_F(GapList, SortingByLengthPutsTheLongestFirst)
{
  std::vector<Gap> gaps = findGaps(doc().take());
  const Eigen::Index longest =
      std::max_element(gaps.begin(), gaps.end(), [](const Gap& a, const Gap& b) { return a.length < b.length; })->length;
  panel->view()->sortByColumn(GapTableModel::LengthColumn, Qt::DescendingOrder);
  QAbstractItemModel* shown = panel->view()->model();
  ASSERT_EQ(shown->rowCount(), static_cast<int>(gaps.size()));
  EXPECT_EQ(shown->index(0, GapTableModel::LengthColumn).data().toLongLong(), longest);
  for (int row = 1; row < shown->rowCount(); ++row)
    EXPECT_GE(shown->index(row - 1, GapTableModel::LengthColumn).data().toLongLong(),
              shown->index(row, GapTableModel::LengthColumn).data().toLongLong());
}

TEST_F(GapList, FiltersByLabelAndByOpenState)
{
  const Take& take = doc().take();
  int section4 = 0;
  for (const Gap& gap : findGaps(take))
    section4 += take.label(gap.marker).rfind("section4-", 0) == 0 ? 1 : 0;
  auto* filter = panel->findChild<QLineEdit*>(QStringLiteral("gapFilter"));
  ASSERT_NE(filter, nullptr);
  QTest::keyClicks(filter, QStringLiteral("Section4"));
  QAbstractItemModel* shown = panel->view()->model();
  EXPECT_EQ(shown->rowCount(), section4) << "case-insensitive label filter";
  for (int row = 0; row < shown->rowCount(); ++row)
    EXPECT_TRUE(shown->index(row, GapTableModel::MarkerColumn).data().toString().startsWith("section4-"));

  // Fill one, which stays listed as filled until "only open gaps" hides it.
  panel->fill(std::vector<int>{rowOf("section4-1", 822)});
  test::waitUntilIdle(*panel);
  const int filledRow = rowOf("section4-1", 822);
  EXPECT_EQ(filledRow, -1) << "no open gap there any more";
  EXPECT_EQ(shown->rowCount(), section4);
  auto* onlyOpen = panel->findChild<QCheckBox*>(QStringLiteral("onlyOpenGaps"));
  ASSERT_NE(onlyOpen, nullptr);
  onlyOpen->setChecked(true);
  EXPECT_EQ(shown->rowCount(), section4 - 1);
  filter->clear();
  EXPECT_EQ(shown->rowCount(), static_cast<int>(findGaps(doc().take()).size()));
}

TEST_F(GapList, DoubleClickSelectsTheMarkerAndFramesTheGap)
{
  ASSERT_TRUE(window->showDock(QStringLiteral("Gaps")));
  QTest::qWait(50);
  const int row = rowOf("section5-1", 1723);
  ASSERT_GE(row, 0);
  QTableView* view = panel->view();
  const QModelIndex index =
      static_cast<QSortFilterProxyModel*>(view->model())->mapFromSource(model->index(row, GapTableModel::LengthColumn));
  view->scrollTo(index);
  const QPoint at = view->visualRect(index).center();
  QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, at);
  QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, at);
  const Eigen::Index marker = *doc().take().markerIndex("section5-1");
  EXPECT_EQ(doc().currentFrame(), 1722);
  ASSERT_EQ(doc().selection(), std::vector<Eigen::Index>{marker});
  const ui::CurveView* curves = window->curveView();
  EXPECT_LT(curves->firstVisible(), 1722.0);
  EXPECT_GT(curves->lastVisible(), 1722.0 + 65.0);
  EXPECT_LT(curves->lastVisible() - curves->firstVisible(), 400.0) << "framed, not the whole take";
}

TEST_F(GapList, FillingTwoCheckedGapsIsOneUndoStepThatRestoresBitForBit)
{
  const Take before = doc().take();
  const int a = rowOf("section3-1", 887), b = rowOf("section4-1", 822);
  ASSERT_GE(a, 0);
  ASSERT_GE(b, 0);
  const Gap gapA = model->gapAt(a), gapB = model->gapAt(b);
  model->setData(model->index(a, GapTableModel::MarkerColumn), Qt::Checked, Qt::CheckStateRole);
  model->setData(model->index(b, GapTableModel::MarkerColumn), Qt::Checked, Qt::CheckStateRole);
  EXPECT_EQ(panel->scopeRows().size(), 2u);
  const int steps = doc().undoStack()->count();
  panel->fill();
  test::waitUntilIdle(*panel);
  ASSERT_EQ(doc().undoStack()->count(), steps + 1) << panel->statusText().toStdString();
  EXPECT_EQ(doc().undoStack()->text(steps), QStringLiteral("Fill 2 gaps: %1").arg(GapTableModel::methodTitle(FillOptions{}.method)));
  const Take& after = doc().take();
  auto inGap = [](const Gap& gap, Eigen::Index m, Eigen::Index f) {
    return m == gap.marker && f >= gap.firstFrame && f < gap.firstFrame + gap.length;
  };
  int changed = 0;
  for (Eigen::Index m = 0; m < before.markerCount(); ++m)
    for (Eigen::Index f = 0; f < before.frameCount(); ++f) {
      if (inGap(gapA, m, f) || inGap(gapB, m, f)) {
        EXPECT_TRUE(after.isValid(f, m)) << m << " " << f;
        EXPECT_EQ(after.state(f, m), SampleOrigin::Filled);
        ++changed;
      } else {
        ASSERT_EQ(after.isValid(f, m), before.isValid(f, m)) << m << " " << f;
        ASSERT_EQ(after.position(f, m), before.position(f, m)) << m << " " << f;
      }
    }
  EXPECT_EQ(changed, 33 + 42);
  EXPECT_EQ(panel->statusText(), QStringLiteral("2 gaps filled, 75 samples"));
  EXPECT_EQ(model->rowCount(), static_cast<int>(findGaps(before).size())) << "filled gaps stay listed";
  EXPECT_TRUE(model->checkedRows().empty()) << "nothing left checked";
  EXPECT_EQ(static_cast<int>(findGaps(after).size()), model->rowCount() - 2);
  doc().undoStack()->undo();
  EXPECT_TRUE(sameSamples(doc().take(), before));
  EXPECT_EQ(model->stateAt(rowOf("section3-1", 887)), GapTableModel::FillState::Open);
}

TEST_F(GapList, EachGapIsFilledWithItsOwnMethod)
{
  const Take before = doc().take();
  const int linear = rowOf("section3-1", 887), spline = rowOf("section13-2", 877);  // 33 and 30 frames
  ASSERT_GE(linear, 0);
  ASSERT_GE(spline, 0);
  const Gap linearGap = model->gapAt(linear), splineGap = model->gapAt(spline);
  ASSERT_TRUE(model->setData(model->index(linear, GapTableModel::MethodColumn), static_cast<int>(FillMethod::Linear)));
  ASSERT_TRUE(model->setData(model->index(spline, GapTableModel::MethodColumn), static_cast<int>(FillMethod::Spline)));
  EXPECT_EQ(cell(linear, GapTableModel::MethodColumn), GapTableModel::methodTitle(FillMethod::Linear));
  model->setCheckedRows({linear, spline}, true);
  panel->fill();
  test::waitUntilIdle(*panel);
  ASSERT_EQ(doc().undoStack()->count(), 1) << panel->statusText().toStdString();
  for (const auto& [gap, method] : {std::pair{linearGap, FillMethod::Linear}, std::pair{splineGap, FillMethod::Spline}}) {
    FillOptions options;  // a gap the technician picked: no bulk limits (see GapListPanel)
    options.method = method;
    options.maxGapSeconds = 0.0;
    options.extrapolate = true;
    options.fillAnyway = {gap.marker};
    const FillResult core = fillGaps(before, std::vector<Gap>{gap}, options);
    ASSERT_EQ(core.patches.size(), 1u);
    const SamplePatch& patch = core.patches.front();
    for (std::size_t i = 0; i < patch.size(); ++i)
      EXPECT_EQ(doc().take().position(patch.frames[i], gap.marker),
                Eigen::Vector3d(patch.positions.row(static_cast<Eigen::Index>(i)).transpose()))
          << fillMethodName(method) << " frame " << patch.frames[i];
  }
}

TEST_F(GapList, AGapThatCannotBeFilledSaysWhy)
{
  const Take& take = doc().take();
  const int row = rowOf("Unlabeled1", 1);  // touches the first frame: nothing to interpolate from
  ASSERT_GE(row, 0);
  const Gap gap = model->gapAt(row);
  ASSERT_TRUE(gap.atEdge);
  model->setMethod(row, FillMethod::Linear);
  // The rules leave it open first; allowed past them, only the method says no.
  EXPECT_NE(model->refusalAt(row), UnfilledCause::None);
  model->setAllowed(row, true);
  EXPECT_TRUE(cell(row, GapTableModel::StateColumn).startsWith("allowed: ")) << cell(row, GapTableModel::StateColumn).toStdString();
  FillOptions options;  // as the panel fills an allowed gap: no rules, so only the method says no
  options.method = FillMethod::Linear;
  options.maxGapSeconds = 0.0;
  options.extrapolate = true;
  options.fillAnyway = {gap.marker};
  const FillResult core = fillGaps(take, std::vector<Gap>{gap}, options);
  ASSERT_FALSE(core.gaps.front().filled);
  panel->fill(std::vector<int>{row});
  test::waitUntilIdle(*panel);
  EXPECT_EQ(doc().undoStack()->count(), 0) << "nothing filled, nothing pushed";
  EXPECT_EQ(model->stateAt(row), GapTableModel::FillState::Unfillable);
  EXPECT_EQ(cell(row, GapTableModel::StateColumn),
            QStringLiteral("cannot fill: %1").arg(QString::fromStdString(core.gaps.front().reason)));
  EXPECT_TRUE(panel->statusText().contains(QString::fromStdString(core.gaps.front().reason)));
}

TEST_F(GapList, SelectingAGapPreviewsItsFillWithoutTouchingTheTake)
{
  test::waitForPreview(*window->cleaningPanel());  // its preview of the open take comes first, then ours replaces it
  ASSERT_TRUE(window->showDock(QStringLiteral("gapListDock")));
  QTest::qWait(50);
  const Take before = doc().take();
  const int row = rowOf("section3-1", 887);
  QTableView* view = panel->view();
  view->selectRow(static_cast<QSortFilterProxyModel*>(view->model())->mapFromSource(model->index(row, 0)).row());
  ASSERT_EQ(panel->scopeRows(), std::vector<int>{row});
  test::waitUntilIdle(*panel);
  ASSERT_EQ(doc().preview().size(), 1u) << panel->statusText().toStdString();
  EXPECT_EQ(doc().preview().front().marker, model->gapAt(row).marker);
  EXPECT_EQ(doc().preview().front().size(), 33u);
  const SamplePatch previewed = doc().preview().front();
  EXPECT_EQ(model->stateAt(row), GapTableModel::FillState::Previewed);
  EXPECT_EQ(panel->statusText(), QStringLiteral("1 gap previewed, 33 samples"));
  EXPECT_TRUE(sameSamples(doc().take(), before));
  EXPECT_EQ(doc().undoStack()->count(), 0);
  panel->fill();
  test::waitUntilIdle(*panel);
  EXPECT_EQ(panel->statusText(), QStringLiteral("1 gap filled, 33 samples"));
  EXPECT_EQ(doc().undoStack()->count(), 1);
  // The gap's preview is gone with the fill (the Cleaning dock, when shown, may preview its own
  // pass over the changed take meanwhile: none of its patches is this gap's).
  for (const SamplePatch& patch : doc().preview())
    EXPECT_FALSE(patch.marker == previewed.marker && patch.frames == previewed.frames) << "the filled gap's preview stays";
}

TEST_F(GapList, AGapOverTheLimitIsPreviewedAndFilledOnlyWhenAllowed)
{
  test::waitForPreview(*window->cleaningPanel());  // its preview of the open take comes first
  ASSERT_TRUE(window->showDock(QStringLiteral("gapListDock")));
  QTest::qWait(50);
  const Take before = doc().take();
  const int row = rowOf("section5-1", 1723);  // 66 frames: over the 0.5 s limit
  QTableView* view = panel->view();
  view->selectRow(static_cast<QSortFilterProxyModel*>(view->model())->mapFromSource(model->index(row, 0)).row());
  test::waitUntilIdle(*panel);
  EXPECT_NE(model->stateAt(row), GapTableModel::FillState::Previewed) << "nothing invented, not even in a preview";
  EXPECT_EQ(panel->statusText(), QStringLiteral("1 gap left open: over the 0.5 s limit"));
  panel->fill();
  test::waitUntilIdle(*panel);
  EXPECT_EQ(doc().undoStack()->count(), 0);
  EXPECT_TRUE(sameSamples(doc().take(), before));

  ASSERT_TRUE(model->setData(model->index(row, GapTableModel::StateColumn), Qt::Checked, Qt::CheckStateRole));
  EXPECT_EQ(cell(row, GapTableModel::StateColumn), QStringLiteral("allowed: over the 0.5 s limit"));
  test::waitUntilIdle(*panel);
  ASSERT_EQ(doc().preview().size(), 1u) << panel->statusText().toStdString();
  EXPECT_EQ(doc().preview().front().size(), 66u);
  // Declined, nothing is filled; confirmed, the 66 samples are, as one undoable step.
  QString asked;
  test::whenModal<QMessageBox>([&asked](QMessageBox* box) {
    asked = box->text();
    box->button(QMessageBox::No)->click();
  });
  panel->fill();
  test::waitUntilIdle(*panel);
  EXPECT_TRUE(asked.startsWith(QStringLiteral("Invent 66 samples: section5-1 frames 1723–1788?"))) << asked.toStdString();
  EXPECT_EQ(doc().undoStack()->count(), 0);
  EXPECT_TRUE(sameSamples(doc().take(), before));
  test::whenModal<QMessageBox>([](QMessageBox* box) { box->button(QMessageBox::Yes)->click(); });
  panel->fill();
  test::waitUntilIdle(*panel);
  ASSERT_EQ(doc().undoStack()->count(), 1) << panel->statusText().toStdString();
  EXPECT_EQ(panel->statusText(), QStringLiteral("1 gap filled, 66 samples"));
  const Eigen::Index marker = *before.markerIndex("section5-1");
  EXPECT_TRUE(doc().take().valid().col(marker).segment(1722, 66).all());
  doc().undoStack()->undo();
  EXPECT_TRUE(sameSamples(doc().take(), before));
}

// The stray marker: seen rarely, with long gaps. Check Shown + Fill on it invents nothing until
// its gaps are allowed one by one, and then only after the confirmation names the samples.
TEST_F(GapList, CheckShownAndFillOnAStrayMarkerFillsNothingWithoutTheOverride)
{
  const Take before = doc().take();
  const Eigen::Index stray = *before.markerIndex("Unlabeled1");
  auto* filter = panel->findChild<QLineEdit*>(QStringLiteral("gapFilter"));
  ASSERT_NE(filter, nullptr);
  filter->setText(QStringLiteral("Unlabeled1"));
  QPushButton* checkShown = nullptr;
  for (QPushButton* button : panel->findChildren<QPushButton*>())
    if (button->text() == QStringLiteral("Check Shown"))
      checkShown = button;
  ASSERT_NE(checkShown, nullptr);
  checkShown->click();
  const std::vector<int> checked = model->checkedRows();
  ASSERT_GE(checked.size(), 2u);
  for (int row : checked) {
    EXPECT_EQ(model->gapAt(row).marker, stray);
    EXPECT_NE(model->refusalAt(row), UnfilledCause::None) << "every gap of the stray marker is past a rule";
    EXPECT_EQ(cell(row, GapTableModel::StateColumn), model->refusalText(row));
  }
  panel->fill();
  test::waitUntilIdle(*panel);
  EXPECT_EQ(doc().undoStack()->count(), 0) << panel->statusText().toStdString();
  EXPECT_TRUE(sameSamples(doc().take(), before));
  EXPECT_TRUE(panel->statusText().contains(QStringLiteral("left open"))) << panel->statusText().toStdString();

  // Allow one interior gap (the context menu's "Allow Filling This Gap" does the same).
  int allowed = -1;
  for (int row : checked)
    if (!model->gapAt(row).atEdge && model->gapAt(row).length > 1 &&
        (allowed < 0 || model->gapAt(row).length < model->gapAt(allowed).length))
      allowed = row;
  ASSERT_GE(allowed, 0);
  const Gap gap = model->gapAt(allowed);  // 7 frames
  model->setMethod(allowed, FillMethod::Linear);  // between its two seen samples, whatever the neighbours do
  model->setAllowed(allowed, true);
  QString asked;
  test::whenModal<QMessageBox>([&asked](QMessageBox* box) {
    asked = box->text();
    box->button(QMessageBox::Yes)->click();
  });
  panel->fill();
  test::waitUntilIdle(*panel);
  const QString expected = QStringLiteral("Invent %1 samples: Unlabeled1 frames %2–%3?")
                               .arg(gap.length)
                               .arg(before.firstFrame() + gap.firstFrame)
                               .arg(before.firstFrame() + gap.firstFrame + gap.length - 1);
  EXPECT_TRUE(asked.startsWith(expected)) << asked.toStdString() << " / " << expected.toStdString();
  ASSERT_EQ(doc().undoStack()->count(), 1) << panel->statusText().toStdString();
  const Take& after = doc().take();
  for (Eigen::Index f = 0; f < before.frameCount(); ++f) {
    const bool inGap = f >= gap.firstFrame && f < gap.firstFrame + gap.length;
    ASSERT_EQ(after.isValid(f, stray), inGap || before.isValid(f, stray)) << f << ": only the allowed gap is filled";
  }
  doc().undoStack()->undo();
  EXPECT_TRUE(sameSamples(doc().take(), before)) << "the fill stays undoable";
}

TEST_F(GapList, FollowsTheCleaningPanelsRules)
{
  const int row = rowOf("section5-1", 1723);
  EXPECT_EQ(model->refusalAt(row), UnfilledCause::TooLong);
  auto* step = window->cleaningPanel()->step<ui::GapFillStep>();
  ASSERT_NE(step, nullptr);
  step->setMaxGapSeconds(1.0);
  EXPECT_EQ(model->refusalAt(rowOf("section5-1", 1723)), UnfilledCause::None);
  EXPECT_EQ(cell(rowOf("section5-1", 1723), GapTableModel::StateColumn), QStringLiteral("open"));
  step->setMaxGapSeconds(0.25);
  EXPECT_EQ(cell(rowOf("section3-1", 887), GapTableModel::StateColumn), QStringLiteral("over the 0.25 s limit"));
}

TEST_F(GapList, FollowsEditsOfTheTake)
{
  const int rows = model->rowCount();
  const Eigen::Index marker = *doc().take().markerIndex("root-3");
  // Make a gap of 20 frames, as Edit ▸ Delete Range does.
  std::vector<SamplePatch> patches{deleteSamples(doc().take(), marker, 100, 119)};
  doc().undoStack()->push(new ui::ApplyPatchesCommand(doc(), std::move(patches), QStringLiteral("Delete")));
  ASSERT_EQ(model->rowCount(), rows + 1);
  const int row = model->rowOf(marker, 100);
  ASSERT_GE(row, 0);
  EXPECT_EQ(model->gapAt(row).length, 20);
  doc().undoStack()->undo();
  EXPECT_EQ(model->rowCount(), rows);
}

TEST_F(GapList, TimelineMarksTheGapsAndBadPointsOfTheSelection)
{
  ui::TimelineWidget* timeline = window->timeline();
  const Take& take = doc().take();
  const Eigen::Index marker = *take.markerIndex("section3-1");  // one gap: file frames 887–919
  doc().setSelection({marker});
  const auto spans = timeline->gapTickSpans();
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans.front(), std::make_pair(timeline->tickX(886), timeline->tickX(918)));
  EXPECT_LT(timeline->tickX(886), timeline->tickX(918));
  EXPECT_TRUE(timeline->flagTickSpans().empty());
  doc().setFlags({{marker, 1500}, {marker + 1, 2500}});
  ASSERT_EQ(timeline->flagTickSpans().size(), 1u) << "only the selected marker's bad point";
  EXPECT_EQ(timeline->flagTickSpans().front(), std::make_pair(timeline->tickX(1500), timeline->tickX(1500)));
  doc().setSelection({});
  EXPECT_EQ(timeline->flagTickSpans().size(), 2u) << "every marker's when none is selected";
  const auto all = timeline->gapTickSpans();
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all.front().first, timeline->tickX(0)) << "Unlabeled1 is missing from the first frame";
}

TEST_F(GapList, PageDownSelectsTheMarkerOfTheNextGapAndSaysWhich)
{
  const Take& take = doc().take();
  const std::vector<Gap> gaps = findGaps(take);
  auto nextAfter = [&](Eigen::Index frame, Eigen::Index marker) {
    const Gap* best = nullptr;
    for (const Gap& gap : gaps)
      if (std::make_tuple(gap.firstFrame, gap.marker) > std::make_tuple(frame, marker) &&
          (!best || std::make_tuple(gap.firstFrame, gap.marker) < std::make_tuple(best->firstFrame, best->marker)))
        best = &gap;
    return best ? *best : Gap{-1, -1, 0, false};
  };
  doc().setSelection({});
  doc().setCurrentFrame(1700);
  ASSERT_TRUE(QTest::qWaitForWindowActive(window.get()));
  QTest::keyClick(window.get(), Qt::Key_PageDown);
  const Gap first = nextAfter(1700, std::numeric_limits<Eigen::Index>::max());
  EXPECT_EQ(doc().currentFrame(), first.firstFrame);
  ASSERT_EQ(doc().selection(), std::vector<Eigen::Index>{first.marker});
  EXPECT_EQ(window->statusBar()->currentMessage(),
            QStringLiteral("Gap of %1 at frame %2 (%3 frames)")
                .arg(QString::fromStdString(take.label(first.marker)))
                .arg(take.firstFrame() + first.firstFrame)
                .arg(first.length));
  // The next PgDn goes on through every marker's gaps, not only the one it selected.
  QTest::keyClick(window.get(), Qt::Key_PageDown);
  const Gap second = nextAfter(first.firstFrame, first.marker);
  EXPECT_NE(second.marker, first.marker) << "the sample has two markers' gaps in a row here";
  EXPECT_EQ(doc().currentFrame(), second.firstFrame);
  EXPECT_EQ(doc().selection(), std::vector<Eigen::Index>{second.marker});
  // A marker the user selects keeps the jumps to its own gaps.
  const Eigen::Index own = *take.markerIndex("Unlabeled1");
  doc().setSelection({own});
  QTest::keyClick(window.get(), Qt::Key_PageDown);
  EXPECT_EQ(doc().selection(), std::vector<Eigen::Index>{own});
  EXPECT_FALSE(take.isValid(doc().currentFrame(), own));
  EXPECT_TRUE(take.isValid(doc().currentFrame() - 1, own));
}

} // namespace
} // namespace mocap

namespace mocap {
namespace {

// The timeline's marks on a 20 000-frame, 60-marker take: worked out once, then painting is per
// pixel column. Prints the times (no threshold: machines differ).
TEST(GapListTimeline, MarksOfALargeTakeAreWorkedOutOnce)
{
  std::vector<std::string> labels;
  for (int m = 0; m < 60; ++m)
    labels.push_back("M" + std::to_string(m));
  Take take(labels, 20000, 100.0);
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
      take.valid()(f, m) = (f + 37 * m) % 500 >= 20;  // a 20-frame gap every 500 frames
  TakeDocument document;
  document.setTake(std::move(take));
  ui::TimelineWidget timeline(document);
  timeline.resize(1200, 40);
  timeline.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&timeline));
  document.setFlags({{0, 5}});  // the marks are stale now: the next call works them out again
  QElapsedTimer clock;
  clock.start();
  const auto spans = timeline.gapTickSpans();
  const double first = static_cast<double>(clock.nsecsElapsed()) * 1e-6;
  clock.restart();
  for (int i = 0; i < 20; ++i)
    timeline.repaint();
  const double paint = static_cast<double>(clock.nsecsElapsed()) * 1e-6 / 20.0;
  EXPECT_FALSE(spans.empty());
  std::cout << "[ measured ] timeline marks of 20000 frames x 60 markers: " << first << " ms to work out, " << paint
            << " ms per repaint\n";
}

TEST(GapListOrigin, AFillThatWasSmoothedStillReadsFilledAndUndoBringsBackTheGap)
{
  // The list follows each sample's origin: smoothing a fill does not make it a measurement.
  Take take({"a"}, 40, 100.0);
  for (Eigen::Index f = 0; f < 40; ++f) {
    take.setPosition(f, 0, Eigen::Vector3d(static_cast<double>(f), 0.0, 0.0));
    take.valid()(f, 0) = f < 10 || f >= 20;
  }
  TakeDocument document;
  document.setTake(std::move(take));
  GapTableModel model(document);
  ASSERT_EQ(model.rowCount(), 1);
  Eigen::Matrix<double, Eigen::Dynamic, 3> positions(10, 3);
  std::vector<Eigen::Index> frames;
  for (Eigen::Index f = 10; f < 20; ++f) {
    positions.row(f - 10) = Eigen::RowVector3d(static_cast<double>(f), 0.0, 0.0);
    frames.push_back(f);
  }
  document.undoStack()->push(
      new ui::ApplyPatchesCommand(document, {makePatch(0, frames, positions, SampleOrigin::Filled)}, QStringLiteral("fill")));
  ASSERT_EQ(model.rowCount(), 1);
  EXPECT_EQ(model.stateAt(0), GapTableModel::FillState::Filled);
  EXPECT_EQ(model.data(model.index(0, GapTableModel::StateColumn)).toString(), QStringLiteral("filled"));
  // Smooth the fill and two measured samples (what a whole-take smoothing does).
  std::vector<Eigen::Index> smoothed;
  std::vector<SampleState> states;
  for (Eigen::Index f = 8; f < 20; ++f) {
    smoothed.push_back(f);
    states.push_back(document.take().state(f, 0).with(SampleOperation::Smoothed));
  }
  SamplePatch smoothing = makePatch(0, smoothed, Eigen::MatrixX3d::Zero(12, 3), SampleOrigin::Measured);
  smoothing.states = states;
  for (Eigen::Index i = 0; i < 12; ++i)
    smoothing.positions.row(i) = document.take().trajectory(0).row(8 + i);
  document.undoStack()->push(new ui::ApplyPatchesCommand(document, {smoothing}, QStringLiteral("smooth")));
  ASSERT_EQ(model.rowCount(), 1) << "the smoothed fill is still listed";
  EXPECT_EQ(model.stateAt(0), GapTableModel::FillState::Filled);
  EXPECT_EQ(model.gapAt(0).firstFrame, 10);
  EXPECT_EQ(model.gapAt(0).length, 10);
  EXPECT_EQ(model.data(model.index(0, GapTableModel::StateColumn)).toString(), QStringLiteral("filled (smoothed)"));
  document.undoStack()->undo();
  EXPECT_EQ(model.data(model.index(0, GapTableModel::StateColumn)).toString(), QStringLiteral("filled"));
  document.undoStack()->undo();
  EXPECT_EQ(model.stateAt(0), GapTableModel::FillState::Open);
}

} // namespace
} // namespace mocap
