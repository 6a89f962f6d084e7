// What a technician's walkthrough on other labs' takes found (issue 30): panels that hide their
// buttons or decisions sideways on the window's first-run size, with long foreign labels.
#include "foreign_takes.h"
#include "job_waits.h"
#include "../core/test_support.h"

#include "document/take_document.h"
#include "main_window.h"
#include "models/gap_table_model.h"
#include "models/marker_table_model.h"
#include "panels/cleaning_panel.h"
#include "panels/gap_list_panel.h"
#include "panels/head_markers_proposal_bar.h"
#include "sample_window.h"
#include "views/marker_view_3d.h"
#include "views/vtk_viewport.h"

#include "mocap/io/take_io.h"

#include <QAction>
#include <QDockWidget>
#include <QFileInfo>
#include <QHeaderView>
#include <QImage>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTableView>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <vtkBillboardTextActor3D.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>
#include <vtkStdString.h>
#include <vtkTextRenderer.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace mocap {
namespace {

// The studio first opens at 85 % of a 1280×800 screen.
constexpr int kWalkWidth = 1088;
constexpr int kWalkHeight = 680;

/// The widest widgets inside `panel`, for a failure message: what keeps it wide.
QString widestChildren(const QWidget& panel, int limit)
{
  QString names;
  for (const QWidget* child : panel.findChildren<QWidget*>())
    if (child->minimumSizeHint().width() > limit)
      names += QStringLiteral("\n  %1 '%2' needs %3 px in %4")
                   .arg(QString::fromLatin1(child->metaObject()->className()), child->objectName())
                   .arg(child->minimumSizeHint().width()).arg(QString::fromLatin1(child->parentWidget()->metaObject()->className()));
  return names;
}

TEST(ForeignTakeWalkthrough, NoDockedPanelScrollsSidewaysAtTheFirstRunSize)
{
  // Cleaning's Apply sat 70 px right of the dock's edge: a technician had to scroll sideways to
  // find it, and the tab of head stabilization was cut. Face Mesh, Blendshape Solve and Reference
  // Video needed 336, 389 and 487 px, their buttons out of view. Every dock that scrolls, checked.
  const auto window = test::openSampleWindow(kWalkWidth, kWalkHeight);
  ASSERT_NE(window, nullptr);
  QString wide;
  int checked = 0;
  for (QDockWidget* dock : window->findChildren<QDockWidget*>()) {
    auto* scroll = qobject_cast<QScrollArea*>(dock->widget());
    if (!scroll)
      continue;  // a dock without a scroll area is as wide as its panel needs
    ++checked;
    dock->show();
    dock->raise();
    QTest::qWait(20);
    const int viewport = scroll->viewport()->width();
    if (scroll->widget()->width() > viewport)
      wide += QStringLiteral("\n%1: panel %2 px in a viewport of %3 px")
                  .arg(dock->objectName())
                  .arg(scroll->widget()->width())
                  .arg(viewport) +
              widestChildren(*scroll->widget(), viewport);
  }
  EXPECT_GE(checked, 6) << "cleaning, gaps, history, face mesh, solve, video";
  EXPECT_TRUE(wide.isEmpty()) << wide.toStdString();
}

TEST(ForeignTakeWalkthrough, MarkersDockShowsTheValidColumnAtTheFirstRunSize)
{
  // The Markers dock showed "Val" and no value: labels as long as "Channel101" (Dance.c3d) took
  // its width. Long labels elide (whole in the tooltip); the valid percentage stays in view.
  const auto window = test::openSampleWindow(kWalkWidth, kWalkHeight);
  ASSERT_NE(window, nullptr);
  ui::TakeDocument& document = window->document();
  for (Eigen::Index marker = 0; marker < document.take().markerCount(); ++marker)
    (void)document.renameMarker(marker, "Skeleton_LShoulder" + std::to_string(marker));
  auto* dock = window->findChild<QDockWidget*>(QStringLiteral("markersDock"));
  ASSERT_NE(dock, nullptr);
  auto* table = qobject_cast<QTableView*>(dock->widget());
  ASSERT_NE(table, nullptr);
  QTest::qWait(50);
  const int valid = ui::MarkerTableModel::ValidColumn;
  EXPECT_LE(table->columnViewportPosition(valid) + table->columnWidth(valid), table->viewport()->width())
      << "label column " << table->columnWidth(ui::MarkerTableModel::LabelColumn) << " px, dock "
      << dock->width() << " px";
  EXPECT_GE(table->columnWidth(valid), table->horizontalHeader()->sectionSizeHint(valid)) << "header cut";
  const QModelIndex label = table->model()->index(0, ui::MarkerTableModel::LabelColumn);
  EXPECT_EQ(label.data(Qt::ToolTipRole).toString(), label.data().toString());
}

TEST(ForeignTakeWalkthrough, ElidedLabelsThatDifferAtTheirEndLookDifferent)
{
  // Dance.c3d's Channel101, Channel102, … all read "Channel1…" in the Markers dock: labels of other
  // systems differ at their end, so a narrow label column elides in the middle.
  const auto window = test::openSampleWindow(kWalkWidth, kWalkHeight);
  ASSERT_NE(window, nullptr);
  ui::TakeDocument& document = window->document();
  (void)document.renameMarker(0, "Skeleton_LShoulder_Channel101");
  (void)document.renameMarker(1, "Skeleton_LShoulder_Channel102");
  QTest::qWait(50);
  const auto looks = [](QTableView& table, int row, int column) {
    const QModelIndex index = table.model()->index(row, column);
    return table.viewport()->grab(table.visualRect(index)).toImage();
  };
  auto* markers = qobject_cast<QTableView*>(window->findChild<QDockWidget*>(QStringLiteral("markersDock"))->widget());
  ASSERT_NE(markers, nullptr);
  const int label = ui::MarkerTableModel::LabelColumn;
  ASSERT_LT(markers->columnWidth(label), markers->fontMetrics().horizontalAdvance(QStringLiteral("Skeleton_LShoulder_Channel101")));
  EXPECT_NE(looks(*markers, 0, label), looks(*markers, 1, label)) << "the Markers dock";
  auto* dock = window->findChild<QDockWidget*>(QStringLiteral("gapListDock"));
  dock->show();
  dock->raise();
  QTest::qWait(50);
  QTableView* gaps = window->gapListPanel()->view();
  gaps->sortByColumn(ui::GapTableModel::MarkerColumn, Qt::AscendingOrder);
  int first = -1, second = -1;
  for (int row = 0; row < gaps->model()->rowCount(); ++row) {
    const QString text = gaps->model()->index(row, ui::GapTableModel::MarkerColumn).data().toString();
    if (first < 0 && text.endsWith(QStringLiteral("101")))
      first = row;
    if (second < 0 && text.endsWith(QStringLiteral("102")))
      second = row;
  }
  if (first >= 0 && second >= 0) {  // both markers have gaps
    EXPECT_NE(looks(*gaps, first, ui::GapTableModel::MarkerColumn), looks(*gaps, second, ui::GapTableModel::MarkerColumn))
        << "the Gaps dock";
  }
}

TEST(ForeignTakeWalkthrough, ADockShownFromTheViewMenuComesToTheFront)
{
  // View ▸ Face Mesh added a tab behind the Gaps dock: nothing seemed to happen.
  const auto window = test::openSampleWindow(kWalkWidth, kWalkHeight);
  ASSERT_NE(window, nullptr);
  for (const char* name : {"faceMeshDock", "blendshapeSolveDock", "referenceVideoDock"}) {
    auto* dock = window->findChild<QDockWidget*>(QString::fromLatin1(name));
    ASSERT_NE(dock, nullptr) << name;
    ASSERT_FALSE(dock->isVisible()) << name;
    dock->toggleViewAction()->trigger();
    QTest::qWait(50);
    EXPECT_FALSE(dock->visibleRegion().isEmpty()) << name << " is behind another tab";
  }
}

/// Where `label` was drawn at the last render: its text's box in display pixels (y up).
QRect drawnLabelBox(vtkBillboardTextActor3D& label, int dpi)
{
  int box[4] = {0, 0, 0, 0};
  vtkTextRenderer::GetInstance()->GetBoundingBox(label.GetTextProperty(), vtkStdString(label.GetInput()), box, dpi);
  const double* anchor = label.GetAnchorDC();
  const int* offset = label.GetDisplayOffset();
  const int x = static_cast<int>(std::lround(anchor[0])) + offset[0];
  const int y = static_cast<int>(std::lround(anchor[1])) + offset[1];
  return QRect(QPoint(x + box[0], y + box[2]), QPoint(x + box[1], y + box[3]));
}

TEST(ForeignTakeWalkthrough, LabelsOfMarkersAtTheViewsEdgeStayInView)
{
  // After Reset Camera the top marker's label was cut by the view's top edge (THEA in Walk1.c3d)
  // and a marker near the right edge showed "Channe" (Dance.c3d).
  const auto window = test::openSampleWindow(kWalkWidth, kWalkHeight);
  ASSERT_NE(window, nullptr);
  ui::MarkerView3d* view = window->markerView();
  ui::VtkViewport* viewport = view->viewport();
  const Take& take = window->document().take();
  view->resetCamera();
  QTest::qWait(100);
  // The markers drawn highest and rightmost in the view.
  const Eigen::Index frame = window->document().currentFrame();
  Eigen::Index top = -1, right = -1;
  QPointF topAt(0, 1e9), rightAt(-1e9, 0);
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    if (!take.isValid(frame, m))
      continue;
    const QPointF at = viewport->widgetPosition(take.position(frame, m));
    if (at.y() < topAt.y())
      std::tie(top, topAt) = std::pair{m, at};
    if (at.x() > rightAt.x())
      std::tie(right, rightAt) = std::pair{m, at};
  }
  ASSERT_GE(top, 0);
  // Long labels, as other systems write them.
  (void)window->document().renameMarker(top, "Skeleton_Head_Top");
  (void)window->document().renameMarker(right, "Skeleton_RShoulder2");
  window->selectLabels({QStringLiteral("Skeleton_Head_Top"), QStringLiteral("Skeleton_RShoulder2")});
  (void)viewport->grabFramebuffer();  // renders now
  const int* size = viewport->renderer()->GetSize();
  const QRect shown(0, 0, size[0], size[1]);
  vtkPropCollection* props = viewport->renderer()->GetViewProps();
  props->InitTraversal();
  int labels = 0;
  while (vtkProp* prop = props->GetNextProp())
    if (auto* label = vtkBillboardTextActor3D::SafeDownCast(prop); label && label->GetVisibility()) {
      ++labels;
      const QRect box = drawnLabelBox(*label, viewport->renderWindow()->GetDPI());
      EXPECT_TRUE(shown.contains(box)) << label->GetInput() << " drawn at (" << box.left() << ", " << box.top()
                                       << ")-(" << box.right() << ", " << box.bottom() << ") in a view of "
                                       << size[0] << "x" << size[1];
    }
  EXPECT_EQ(labels, 2);
}

TEST(ForeignTakeWalkthrough, GapStatesStayInViewWithLongMarkerLabels)
{
  // A NaturalPoint skeleton's labels ("Skeleton_LShoulder2") pushed the Gaps dock's state column,
  // which says why a gap stays open, out of view.
  const auto window = test::openSampleWindow(kWalkWidth, kWalkHeight);
  ASSERT_NE(window, nullptr);
  ui::TakeDocument& document = window->document();
  for (Eigen::Index marker = 0; marker < document.take().markerCount(); ++marker)
    (void)document.renameMarker(marker, "Skeleton_LShoulder" + std::to_string(marker));
  auto* dock = window->findChild<QDockWidget*>(QStringLiteral("gapListDock"));
  ASSERT_NE(dock, nullptr);
  dock->show();
  dock->raise();
  QTest::qWait(50);
  QTableView* view = window->gapListPanel()->view();
  ASSERT_GT(view->model()->rowCount(), 0);
  const int visible = view->viewport()->width();
  const int state = ui::GapTableModel::StateColumn;
  EXPECT_LE(view->columnViewportPosition(state) + view->columnWidth(state), visible)
      << "marker column " << view->columnWidth(ui::GapTableModel::MarkerColumn) << " px";
  // The elided label stays readable in full.
  const QString label = view->model()->index(0, ui::GapTableModel::MarkerColumn).data().toString();
  EXPECT_EQ(view->model()->index(0, ui::GapTableModel::MarkerColumn).data(Qt::ToolTipRole).toString(), label);
}

TEST(ForeignTakeWalkthrough, SavedMessageIsNotCutByTheModelOutputsNote)
{
  // On a Nexus take the note "34 model outputs (12 angles, …) hidden; View ▸ Show Model Outputs"
  // took the status bar's width: "Saved /tmp/walk/pig_clean.c3d" showed as "Saved /tmp/walk/pig_c".
  test::TempDir dir;
  writeTake(test::nexusCleaningTake(), dir.file("nexus.c3d"));
  const auto window = test::openSampleWindow(kWalkWidth, kWalkHeight);
  ASSERT_NE(window, nullptr);
  ASSERT_EQ(window->openFile(QString::fromStdString(dir.file("nexus.c3d").string()), true), QString());
  QTest::qWait(20);
  int permanentLeft = window->statusBar()->width();
  for (const QWidget* child : window->statusBar()->findChildren<QWidget*>(Qt::FindDirectChildrenOnly))
    if (child->isVisible() && child->x() > 0)
      permanentLeft = std::min(permanentLeft, child->x());
  const QString saved = QStringLiteral("Saved /home/technician/takes/pig_clean_v2.c3d");
  EXPECT_GE(permanentLeft, window->statusBar()->fontMetrics().horizontalAdvance(saved) + 10)
      << "room left for messages: " << permanentLeft << " px";
}

TEST(ForeignTakeWalkthrough, CtrlReturnFillsWithTheGapTableFocused)
{
  // After checking a gap in the table (the table has the focus), Ctrl+Return filled nothing.
  const auto window = test::openSampleWindow(kWalkWidth, kWalkHeight);
  ASSERT_NE(window, nullptr);
  auto* dock = window->findChild<QDockWidget*>(QStringLiteral("gapListDock"));
  ASSERT_NE(dock, nullptr);
  dock->show();
  dock->raise();
  ui::GapListPanel& panel = *window->gapListPanel();
  ui::GapTableModel& model = *panel.model();
  ASSERT_GT(model.rowCount(), 0);
  int row = 0;
  while (row < model.rowCount() && model.stateAt(row) != ui::GapTableModel::FillState::Open)
    ++row;
  ASSERT_LT(row, model.rowCount());
  model.setData(model.index(row, ui::GapTableModel::MarkerColumn), Qt::Checked, Qt::CheckStateRole);
  test::waitUntilIdle(panel);
  QTableView* view = panel.view();
  view->setFocus();
  QTest::qWait(20);
  const int steps = window->document().undoStack()->count();
  QTest::keyClick(view, Qt::Key_Return, Qt::ControlModifier);
  QTest::qWait(300);  // a button's shortcut clicks it after a short animation
  test::waitUntilIdle(panel);
  EXPECT_EQ(window->document().undoStack()->count(), steps + 1) << panel.statusText().toStdString();
  view->setFocus();
  QTest::keyClick(view, Qt::Key_Z, Qt::ControlModifier);
  EXPECT_EQ(window->document().undoStack()->index(), steps) << "Ctrl+Z undoes with the table focused";
}

/// Opens a file of the test data in `window`, quietly (no warnings dialog).
bool openForeignTake(studio::MainWindow& window, const char* file)
{
  const QString error = window.openFile(QString::fromStdString(test::dataFile(file).string()), true);
  EXPECT_EQ(error, QString()) << file;
  QTest::qWait(50);
  return error.isEmpty();
}

TEST(ForeignTakeWalkthrough, ElidedLabelsWithASubjectPrefixLookDifferent)
{
  // ART's labels carry their subject ("Human3:LLSP", "Human3:ULSP", "Tools:TOOL1Y"): eliding in the
  // middle kept the prefix and lost the name, "Hum…LSP" twice in the Markers dock.
  const auto window = test::openSampleWindow(kWalkWidth, kWalkHeight);
  ASSERT_NE(window, nullptr);
  ASSERT_TRUE(openForeignTake(*window, "c3d/sample37/ART-Human_tools_integer_6dofLimbs.c3d"));
  auto* markers = qobject_cast<QTableView*>(window->findChild<QDockWidget*>(QStringLiteral("markersDock"))->widget());
  ASSERT_NE(markers, nullptr);
  const int label = ui::MarkerTableModel::LabelColumn;
  ASSERT_LT(markers->columnWidth(label), markers->fontMetrics().horizontalAdvance(QStringLiteral("Human3:LHANY")));
  std::vector<std::pair<QString, QImage>> drawn;
  for (int row = 0; row < markers->model()->rowCount(); ++row) {
    const QModelIndex index = markers->model()->index(row, label);
    markers->scrollTo(index);
    drawn.emplace_back(index.data().toString(), markers->viewport()->grab(markers->visualRect(index)).toImage());
  }
  ASSERT_EQ(drawn.size(), 37u);
  QString alike;
  for (std::size_t a = 0; a < drawn.size(); ++a)
    for (std::size_t b = a + 1; b < drawn.size(); ++b)
      if (drawn[a].second == drawn[b].second)
        alike += QStringLiteral(" %1=%2").arg(drawn[a].first, drawn[b].first);
  EXPECT_TRUE(alike.isEmpty()) << "drawn alike:" << alike.toStdString();
}

TEST(ForeignTakeWalkthrough, SixTabbedDocksShowTheirTitlesWhole)
{
  // With Face Mesh, Blendshape Solve and Reference Video shown beside Cleaning, Layout planning and
  // Gaps, the side dock's tabs read "Cl…", "La…", "Ga…": every title was elided.
  const auto window = test::openSampleWindow(kWalkWidth, kWalkHeight);
  ASSERT_NE(window, nullptr);
  for (const char* name : {"faceMeshDock", "blendshapeSolveDock", "referenceVideoDock"})
    window->findChild<QDockWidget*>(QString::fromLatin1(name))->toggleViewAction()->trigger();
  QTest::qWait(50);
  int most = 0;
  for (const QTabBar* tabs : window->findChildren<QTabBar*>(Qt::FindDirectChildrenOnly)) {
    if (!tabs->isVisible())
      continue;
    most = std::max(most, tabs->count());
    for (int i = 0; i < tabs->count(); ++i)
      EXPECT_GE(tabs->tabRect(i).width(), tabs->fontMetrics().horizontalAdvance(tabs->tabText(i)))
          << tabs->tabText(i).toStdString() << " in a tab bar of " << tabs->width() << " px";
  }
  EXPECT_GE(most, 6);
}

TEST(ForeignTakeWalkthrough, CleaningTabsShowWholeAtTheFirstRunSize)
{
  // On a 1280×800 screen the Cleaning panel's fourth tab read "Sta" behind the scroll arrows.
  const auto window = test::openSampleWindow(kWalkWidth, kWalkHeight);
  ASSERT_NE(window, nullptr);
  ASSERT_TRUE(window->showDock(QStringLiteral("cleaningDock")));
  QTest::qWait(50);
  auto* panel = window->findChild<ui::CleaningPanel*>();
  ASSERT_NE(panel, nullptr);
  const QTabBar* tabs = panel->findChild<QTabWidget*>()->tabBar();
  ASSERT_EQ(tabs->count(), 4);
  for (int i = 0; i < tabs->count(); ++i) {
    EXPECT_GE(tabs->tabRect(i).left(), 0) << tabs->tabText(i).toStdString();
    EXPECT_LE(tabs->tabRect(i).right(), tabs->width() - 1)
        << tabs->tabText(i).toStdString() << " ends at " << tabs->tabRect(i).right() << " in a tab bar of "
        << tabs->width() << " px";
    EXPECT_GE(tabs->tabRect(i).width(), tabs->fontMetrics().horizontalAdvance(tabs->tabText(i)));
    EXPECT_FALSE(tabs->tabToolTip(i).isEmpty()) << "the step's whole title";
  }
}

TEST(ForeignTakeWalkthrough, CleaningApplyAndPreviewOptionsInViewWithoutScrolling)
{
  // On a 1600×1000 screen Apply sat below the fold of the Cleaning dock: the dock scrolled, and a
  // technician had to scroll to apply what the preview showed. On every tab, at the first-run
  // sizes of a 1600×1000 and a 1280×800 screen, Apply and the preview options are in the dock's
  // view with the dock scrolled to its top, and the dock does not scroll up and down at all.
  for (const QSize size : {QSize(1360, 850), QSize(kWalkWidth, kWalkHeight)}) {
    const auto window = test::openSampleWindow(size.width(), size.height());
    ASSERT_NE(window, nullptr);
    ASSERT_TRUE(window->showDock(QStringLiteral("cleaningDock")));
    auto* dock = window->findChild<QDockWidget*>(QStringLiteral("cleaningDock"));
    ASSERT_NE(dock, nullptr);
    auto* panel = window->findChild<ui::CleaningPanel*>();
    ASSERT_NE(panel, nullptr);
    auto* tabs = panel->findChild<QTabWidget*>();
    ASSERT_NE(tabs, nullptr);
    for (int tab = 0; tab < tabs->count(); ++tab) {
      tabs->setCurrentIndex(tab);
      test::waitForPreview(*panel);  // the bad points' list filled, the status said
      QTest::qWait(50);
      const std::string where = std::to_string(size.width()) + "x" + std::to_string(size.height()) + ", tab " +
                                tabs->tabText(tab).toStdString();
      if (auto* scroll = qobject_cast<QScrollArea*>(dock->widget())) {
        EXPECT_LE(scroll->widget()->height(), scroll->viewport()->height())
            << where << ": the dock scrolls up and down";
      }
      for (const char* name : {"applyCleaning", "cleaningLivePreview", "rangeOnly"}) {
        const auto* widget = panel->findChild<QWidget*>(QString::fromLatin1(name));
        ASSERT_NE(widget, nullptr) << name;
        EXPECT_TRUE(widget->isVisible()) << name << ", " << where;
        const QRect shown(widget->mapTo(dock, QPoint(0, 0)), widget->size());
        EXPECT_TRUE(dock->rect().contains(shown))
            << name << " at y " << shown.top() << ".." << shown.bottom() << " in a dock " << dock->height()
            << " px high, " << where;
      }
    }
  }
}

TEST(ForeignTakeWalkthrough, MarkersDockShowsEveryColumnWholeOnA1600Screen)
{
  // On a 1600×1000 screen (the first window 1360×850) the Markers dock cut its third column.
  const auto window = test::openSampleWindow(1360, 850);
  ASSERT_NE(window, nullptr);
  auto* dock = window->findChild<QDockWidget*>(QStringLiteral("markersDock"));
  ASSERT_NE(dock, nullptr);
  auto* table = qobject_cast<QTableView*>(dock->widget());
  ASSERT_NE(table, nullptr);
  QTest::qWait(50);
  for (int column = 0; column < ui::MarkerTableModel::ColumnCount; ++column)
    EXPECT_LE(table->columnViewportPosition(column) + table->columnWidth(column), table->viewport()->width())
        << "column " << column << ", dock " << dock->width() << " px";
  EXPECT_GE(window->markerView()->width(), window->width() * 40 / 100) << "the 3D view keeps 40 %";
}

TEST(ForeignTakeWalkthrough, ReadWarningsNameTheFileReadAfterSaveAs)
{
  // After Save As, the warnings list said "1 warning(s) while reading pig_saved.c3d": the saved copy
  // reads without them (its types are listed); they are the original file's.
  const auto window = test::openSampleWindow(kWalkWidth, kWalkHeight);
  ASSERT_NE(window, nullptr);
  ASSERT_TRUE(openForeignTake(*window, "c3d/sample03/gait-pig-nz.c3d"));
  ui::TakeDocument& document = window->document();
  ASSERT_EQ(document.loadWarnings().size(), 1u) << "Plug-in Gait's virtual points";
  test::TempDir dir;
  const QString saved = QString::fromStdString(dir.file("pig_saved.c3d").string());
  ASSERT_TRUE(document.save(saved, true).isEmpty());
  EXPECT_EQ(document.filePath(), saved);
  EXPECT_EQ(QFileInfo(document.readFilePath()).fileName(), QStringLiteral("gait-pig-nz.c3d"));
  std::vector<std::string> again;
  (void)readTake(saved.toStdString(), &again);
  EXPECT_TRUE(again.empty()) << again.front();
}

TEST(ForeignTakeWalkthrough, NoHeadMarkersAreProposedOnAGaitTake)
{
  // On Vicon's gait-pig the bar proposed "Head markers guessed: RASI, LASI, SACR", the pelvis.
  const auto window = test::openSampleWindow(kWalkWidth, kWalkHeight);
  ASSERT_NE(window, nullptr);
  auto* bar = window->findChild<ui::HeadMarkersProposalBar*>(QStringLiteral("headMarkersProposalBar"));
  ASSERT_NE(bar, nullptr);
  ASSERT_TRUE(openForeignTake(*window, "c3d/sample03/gait-pig-nz.c3d"));
  EXPECT_TRUE(window->document().proposedReferenceMarkers().empty());
  EXPECT_FALSE(bar->isVisible()) << bar->text().toStdString();
}

} // namespace
} // namespace mocap
