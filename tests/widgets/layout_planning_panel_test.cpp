// The layout planning dock end to end under Xvfb: plan the sample with few restarts, read the
// plot, click a marker count and check the 3D highlight, cancel, export, and refuse bad input.
#include "job_waits.h"
#include "../core/test_support.h"

#include "document/layout_plan_model.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "main_window.h"
#include "sample_window.h"
#include "panels/layout_planning_panel.h"
#include "views/layout_error_plot.h"
#include "views/marker_view_3d.h"

#include "mocap/base/file_io.h"
#include "mocap/io/marker_set_io.h"
#include "mocap/io/take_io.h"

#include <QDockWidget>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QTableWidget>
#include <QTest>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mocap {
namespace {

using studio::MainWindow;
using ui::LayoutErrorPlot;
using ui::LayoutPlanningPanel;

const QStringList kReference = {"root-1", "root-2", "root-3", "root-4", "root-5", "root-6"};

class LayoutPlanning : public ::testing::Test
{
protected:
  void SetUp() override
  {
    window = test::openSampleWindow(1280, 900);
    ASSERT_NE(window, nullptr);
    window->findChild<QDockWidget*>(QStringLiteral("layoutPlanningDock"))->raise();  // tabbed behind Cleaning
    panel = window->layoutPlanningPanel();
    ASSERT_NE(panel, nullptr);
  }

  /// Few restarts and a small k range: a few seconds, yet several marker counts.
  static ui::LayoutPlanParameters quick()
  {
    ui::LayoutPlanParameters p;
    p.restarts = 5;
    p.minK = 3;
    p.maxK = 12;
    p.seed = 7;  // the reference markers are the take's (root-1…6, guessed when it opened)
    return p;
  }

  /// Runs quick() to the end (call through ASSERT_NO_FATAL_FAILURE).
  void runQuickPlan()
  {
    panel->setParameters(quick());
    ASSERT_EQ(panel->run(), QString());
    EXPECT_TRUE(panel->busy() || layoutPlan().result() == nullptr);
    ASSERT_TRUE(test::waitForJob(panel->jobs()));
    ASSERT_FALSE(panel->busy());
    ASSERT_NE(layoutPlan().result(), nullptr) << panel->statusText().toStdString();
  }

  /// The take's labels the 3D view draws as kept.
  std::vector<std::string> highlightedLabels() const
  {
    const std::vector<bool>& kept = window->markerView()->layoutHighlight();
    std::vector<std::string> labels;
    for (std::size_t m = 0; m < kept.size(); ++m)
      if (kept[m])
        labels.push_back(window->document().take().label(static_cast<Eigen::Index>(m)));
    std::sort(labels.begin(), labels.end());
    return labels;
  }

  /// The session's layout plan, which the dock fills.
  [[nodiscard]] ui::LayoutPlanModel& layoutPlan() const { return window->session().layoutPlan(); }

  static std::vector<std::string> sorted(std::vector<std::string> labels)
  {
    std::sort(labels.begin(), labels.end());
    return labels;
  }

  std::unique_ptr<MainWindow> window;
  LayoutPlanningPanel* panel = nullptr;
};

TEST_F(LayoutPlanning, PlansTheSampleAndHighlightsTheClickedSize)
{
  ASSERT_NO_FATAL_FAILURE(runQuickPlan());
  const LayoutPlan& plan = layoutPlan().result()->plan;
  // Neither the reference markers nor the unlabelled point (Unlabeled1) are planned.
  EXPECT_EQ(layoutPlan().result()->frames.markerCount(), 31);
  LayoutErrorPlot* plot = panel->plot();
  for (const auto measure : {LayoutErrorPlot::Measure::ReconstructionRmse, LayoutErrorPlot::Measure::BlendshapeMse}) {
    EXPECT_GE(plot->points(measure, LayoutErrorPlot::Curve::Pfa).size(), 3u);
    EXPECT_GE(plot->points(measure, LayoutErrorPlot::Curve::Greedy).size(), 3u);
    EXPECT_GE(plot->points(measure, LayoutErrorPlot::Curve::Random).size(), 3u);
  }
  ASSERT_GT(plot->recommendedSize(), 0);
  EXPECT_EQ(plot->recommendedSize(), plan.recommendedSize);
  EXPECT_EQ(plot->selectedSize(), plan.recommendedSize);
  // Fewer markers reconstruct worse: the first PFA point is drawn higher (smaller y) than the last.
  const auto rmse = plot->points(LayoutErrorPlot::Measure::ReconstructionRmse, LayoutErrorPlot::Curve::Pfa);
  EXPECT_LT(rmse.front().y(), rmse.back().y());
  EXPECT_GT(rmse.front().x(), 0.0);
  EXPECT_LT(rmse.back().x(), plot->width());

  // The recommended layout is highlighted straight away.
  EXPECT_EQ(highlightedLabels(), sorted(layoutPlan().selectedLabels()));
  EXPECT_EQ(static_cast<Eigen::Index>(layoutPlan().selectedLabels().size()), plan.recommendedSize);

  // Click another size on the plot.
  const auto& sizes = plot->selectableSizes();
  ASSERT_GE(sizes.size(), 2u);
  const Eigen::Index target = sizes.front() != plot->selectedSize() ? sizes.front() : sizes.back();
  QTest::mouseClick(plot, Qt::LeftButton, {}, QPoint(static_cast<int>(std::lround(plot->xOf(target))), plot->height() / 2));
  ASSERT_EQ(plot->selectedSize(), target);
  const ScoredLayout* layout = plan.size(target)->layout(plan.method);
  ASSERT_NE(layout, nullptr);
  std::vector<std::string> expected;
  for (const Eigen::Index m : layout->markers)
    expected.push_back(layoutPlan().result()->frames.labels[static_cast<std::size_t>(m)]);
  EXPECT_EQ(highlightedLabels(), sorted(expected));
  EXPECT_EQ(static_cast<Eigen::Index>(expected.size()), target);
  EXPECT_EQ(window->markerView()->layoutHighlight().size(), 38u);
  // The table lists the layout's markers with their pair frequency.
  auto* table = panel->findChild<QTableWidget*>();
  ASSERT_NE(table, nullptr);
  ASSERT_EQ(table->rowCount(), static_cast<int>(target));
  EXPECT_EQ(table->item(0, 0)->text().toStdString(), expected.front());
  EXPECT_TRUE(table->item(0, 2)->text().endsWith(QStringLiteral("%"))) << table->item(0, 2)->text().toStdString();

  // ←/→ step through the sizes when the plot has the focus, not through frames.
  plot->setFocus();
  const Eigen::Index frame = window->document().currentFrame();
  const auto at = std::find(sizes.begin(), sizes.end(), target) - sizes.begin();
  const Eigen::Index neighbour = at == 0 ? sizes[1] : sizes[static_cast<std::size_t>(at - 1)];
  QTest::keyClick(plot, at == 0 ? Qt::Key_Right : Qt::Key_Left);
  EXPECT_EQ(plot->selectedSize(), neighbour);
  EXPECT_EQ(static_cast<Eigen::Index>(highlightedLabels().size()), neighbour);
  EXPECT_EQ(window->document().currentFrame(), frame);

  // Another take ends the highlight.
  window->document().setTake(Take({"a", "b"}, 5, 100.0));
  EXPECT_TRUE(window->markerView()->layoutHighlight().empty());
}

TEST_F(LayoutPlanning, HighlightsOnlyWhileItsTabIsInFront)
{
  // A plan of three of the take's markers, two of them picked.
  const Take& take = window->document().take();
  auto plan = std::make_shared<ui::LayoutPlanResult>();
  plan->frames.labels = {take.label(7), take.label(8), take.label(9)};
  plan->symmetry = MarkerSymmetry(3, {});
  LayoutSize size;
  size.markerCount = 2;
  size.pfa = ScoredLayout{};
  size.pfa->markers = {0, 2};
  plan->plan.sizes.push_back(size);
  const std::vector<std::string> picked = sorted({take.label(7), take.label(9)});

  // As after a recovery: the window's layout restored with Cleaning in front, then the plan set.
  auto* cleaningDock = window->findChild<QDockWidget*>(QStringLiteral("cleaningDock"));
  auto* layoutDock = window->findChild<QDockWidget*>(QStringLiteral("layoutPlanningDock"));
  cleaningDock->raise();
  ASSERT_TRUE(window->restoreState(window->saveState()));
  QTest::qWait(50);
  ASSERT_TRUE(layoutDock->isVisible()) << "Qt calls a tab behind another visible";
  layoutPlan().setResult(plan, 2);
  EXPECT_TRUE(highlightedLabels().empty()) << "highlighted behind the Cleaning tab";

  layoutDock->raise();
  EXPECT_EQ(highlightedLabels(), picked);
  cleaningDock->raise();
  EXPECT_TRUE(highlightedLabels().empty());
  layoutPlan().setSelectedSize(2);  // a change while behind shows nothing either
  EXPECT_TRUE(highlightedLabels().empty());
  layoutDock->raise();
  EXPECT_EQ(highlightedLabels(), picked);
  layoutDock->close();
  EXPECT_TRUE(highlightedLabels().empty());
}

TEST_F(LayoutPlanning, CancelStopsTheRunAndLeavesThePanelIdle)
{
  ui::LayoutPlanParameters slow = quick();
  slow.restarts = 1000;
  slow.minK = 0;
  slow.maxK = 0;
  panel->setParameters(slow);
  ASSERT_EQ(panel->run(), QString());
  ASSERT_TRUE(panel->busy());
  EXPECT_NE(panel->run(), QString());  // one run at a time
  QTest::qWait(200);
  panel->cancel();
  ASSERT_TRUE(test::waitForJob(panel->jobs()));
  EXPECT_FALSE(panel->busy());
  EXPECT_EQ(layoutPlan().result(), nullptr);
  EXPECT_TRUE(panel->statusText().contains(QStringLiteral("Cancel"))) << panel->statusText().toStdString();
  EXPECT_TRUE(window->markerView()->layoutHighlight().empty());
  // Idle again: a new run starts.
  panel->setParameters(quick());
  EXPECT_EQ(panel->run(), QString());
  ASSERT_TRUE(test::waitForJob(panel->jobs()));
  EXPECT_NE(layoutPlan().result(), nullptr);
}

TEST_F(LayoutPlanning, ExportsTheSelectedLayout)
{
  ASSERT_NO_FATAL_FAILURE(runQuickPlan());
  const std::vector<std::string> labels = layoutPlan().selectedLabels();
  ASSERT_FALSE(labels.empty());
  test::TempDir dir;
  const QString list = QString::fromStdString(dir.file("layout.txt").string());
  ASSERT_EQ(panel->exportLabelList(list), QString());
  std::istringstream text(readFileBytes(dir.file("layout.txt")));
  std::vector<std::string> lines;
  for (std::string line; std::getline(text, line);)
    lines.push_back(line);
  EXPECT_EQ(lines, labels);

  // The take and the marker set keep the head reference markers a reduced capture still needs.
  std::vector<std::string> capture = labels;
  for (const QString& label : kReference)
    capture.push_back(label.toStdString());
  ASSERT_EQ(panel->exportTake(QString::fromStdString(dir.file("reduced.c3d").string())), QString());
  const Take reduced = readTake(dir.file("reduced.c3d"));
  EXPECT_EQ(reduced.labels(), capture);
  EXPECT_EQ(reduced.frameCount(), window->document().take().frameCount());
  ASSERT_EQ(panel->exportMarkerSet(QString::fromStdString(dir.file("reduced.json").string())), QString());
  const MarkerSet set = readMarkerSet(dir.file("reduced.json"));
  EXPECT_EQ(sorted(set.labels), sorted(capture));
  // Every pair in the file is a pair the plan kept together.
  const MarkerSymmetry& symmetry = layoutPlan().result()->symmetry;
  const auto& planned = layoutPlan().result()->frames.labels;
  for (const auto& [a, b] : set.pairs) {
    const auto ia = std::find(planned.begin(), planned.end(), set.labels[static_cast<std::size_t>(a)]) - planned.begin();
    const auto ib = std::find(planned.begin(), planned.end(), set.labels[static_cast<std::size_t>(b)]) - planned.begin();
    EXPECT_EQ(symmetry.mirror(ia), ib);
  }

  // A folder that does not exist is an error message, and nothing is written.
  EXPECT_NE(panel->exportLabelList(QString::fromStdString(dir.file("missing/layout.txt").string())), QString());
}

TEST_F(LayoutPlanning, RefusesBadInputWithAMessage)
{
  ui::LayoutPlanParameters p = quick();
  p.minK = 9;
  p.maxK = 3;
  panel->setParameters(p);
  EXPECT_NE(panel->run(), QString());
  EXPECT_FALSE(panel->busy());
  p = quick();
  p.excludePatterns = {QStringLiteral("no-such-marker")};
  panel->setParameters(p);
  EXPECT_TRUE(panel->run().contains(QStringLiteral("no-such-marker")));
  p = quick();
  p.extraTakes = {QStringLiteral("/no/such/take.c3d")};
  panel->setParameters(p);
  ASSERT_EQ(panel->run(), QString());  // read on the worker: the failure arrives as the result
  ASSERT_TRUE(test::waitForJob(panel->jobs()));
  EXPECT_EQ(layoutPlan().result(), nullptr);
  EXPECT_TRUE(panel->statusText().contains(QStringLiteral("take.c3d"))) << panel->statusText().toStdString();
}

// The panel asks what `mocap pfa` asks: globs, key poses and the random baseline reach the plan.
TEST_F(LayoutPlanning, GlobsKeyPosesAndRandomSetsReachThePlan)
{
  ui::LayoutPlanParameters p = quick();
  p.excludePatterns = {QStringLiteral("section1-*"), QStringLiteral("section2-?")};
  p.randomSubsets = 0;
  p.keyPoses = QStringLiteral("lots");
  panel->setParameters(p);
  EXPECT_TRUE(panel->run().contains(QStringLiteral("lots"))) << "a malformed key pose is refused at once";
  EXPECT_FALSE(panel->busy());

  p.keyPoses.clear();
  panel->setParameters(p);
  ASSERT_EQ(panel->run(), QString());
  ASSERT_TRUE(test::waitForJob(panel->jobs()));
  ASSERT_NE(layoutPlan().result(), nullptr) << panel->statusText().toStdString();
  const LayoutResult& result = *layoutPlan().result();
  for (const std::string& label : result.frames.labels)
    EXPECT_TRUE(label.rfind("section1-", 0) != 0 && label.rfind("section2-", 0) != 0) << label;
  for (const LayoutSize& size : result.plan.sizes)
    EXPECT_EQ(size.randomCount, 0) << "no random sets were asked for";

  // Key poses by frame number: the plan's basis uses exactly those frames.
  std::vector<Eigen::Index> rows;
  QStringList frames;
  for (const std::size_t at : {result.frames.training.size() / 4, result.frames.training.size() / 2}) {
    const Eigen::Index row = result.frames.training[at];
    rows.push_back(row);
    frames << QString::number(result.frames.origin[static_cast<std::size_t>(row)].second + window->document().take().firstFrame());
  }
  p.keyPoses = frames.join(QStringLiteral(","));
  panel->setParameters(p);
  ASSERT_EQ(panel->run(), QString());
  ASSERT_TRUE(test::waitForJob(panel->jobs()));
  ASSERT_NE(layoutPlan().result(), nullptr) << panel->statusText().toStdString();
  EXPECT_EQ(layoutPlan().result()->plan.basis.keyFrames, rows);
}

TEST_F(LayoutPlanning, ScrollsRatherThanForcingTheWindowTaller)
{
  window->resize(1280, 800);  // the --screenshot size
  QTest::qWait(50);
  EXPECT_EQ(window->height(), 800);
  EXPECT_LE(panel->minimumSizeHint().height(), 300);
  auto* scroll = panel->findChild<QScrollArea*>();
  ASSERT_NE(scroll, nullptr);
  EXPECT_FALSE(scroll->horizontalScrollBar()->isVisible()) << "the form fits the dock's width: no sideways scrolling";
}

TEST_F(LayoutPlanning, RemembersItsParameters)
{
  ui::LayoutPlanParameters p = quick();
  p.method = SelectionMethod::Greedy;
  p.variance = 0.95;
  p.minK = 3;
  p.maxK = 4;
  p.randomSubsets = 2;
  p.markerPatterns = {QStringLiteral("section*")};
  p.excludePatterns = {QStringLiteral("section14-*")};
  panel->setParameters(p);
  ASSERT_EQ(panel->run(), QString());
  ASSERT_TRUE(test::waitForJob(panel->jobs()));
  LayoutPlanningPanel fresh(window->session());
  const ui::LayoutPlanParameters remembered = fresh.parameters();
  EXPECT_EQ(remembered.method, SelectionMethod::Greedy);
  EXPECT_EQ(remembered.randomSubsets, 2);
  EXPECT_EQ(remembered.markerPatterns, p.markerPatterns);
  EXPECT_EQ(remembered.excludePatterns, p.excludePatterns);
  EXPECT_DOUBLE_EQ(remembered.variance, 0.95);
  EXPECT_EQ(remembered.restarts, 5);
  EXPECT_EQ(remembered.minK, 3);
  EXPECT_EQ(remembered.maxK, 4);
  EXPECT_EQ(remembered.seed, 7);
}

} // namespace
} // namespace mocap
