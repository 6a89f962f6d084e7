// The studio end to end under Xvfb: open, select, edit with undo/redo, save, render, errors.
#include "job_waits.h"
#include "../core/test_support.h"
#include "image_difference.h"
#include "screen_pixels.h"

#include "commands/apply_patches_command.h"
#include "commands/insert_marker_command.h"
#include "commands/remove_markers_command.h"
#include "commands/set_reference_markers_command.h"
#include "dialogs/swap_review_dialog.h"
#include "document/take_document.h"
#include "language.h"
#include "main_window.h"
#include "sample_window.h"
#include "models/marker_table_model.h"
#include "panels/cleaning_panel.h"
#include "panels/gap_fill_step.h"
#include "panels/head_stabilization_step.h"
#include "views/curve_view.h"
#include "views/marker_view_3d.h"
#include "views/sample_colors.h"
#include "views/timeline_widget.h"
#include "views/vtk_viewport.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/io/c3d_writer.h"
#include "mocap/base/file_io.h"
#include "mocap/model/gaps.h"
#include "mocap/model/marker_links.h"
#include "mocap/model/marker_set.h"
#include "checkout_paths.h"

#include <QAction>
#include <QApplication>
#include <QImage>
#include <QItemSelectionModel>
#include <QListWidget>
#include <QMouseEvent>
#include <QSettings>
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QLibraryInfo>
#include <QPushButton>
#include <QElapsedTimer>
#include <QLabel>
#include <QTableView>
#include <QToolTip>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace mocap {
namespace {

using studio::MainWindow;
using ui::TakeDocument;

/// Where the viewport's camera puts `world`, in widget (logical) coordinates: the camera's
/// composite projection matrix applied here, independently of the view's own picking code.
QPointF projectThroughCamera(ui::VtkViewport& viewport, const Eigen::Vector3d& world)
{
  const double aspect = double(viewport.width()) / double(viewport.height());
  vtkMatrix4x4* vtkProjection =
      viewport.renderer()->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0);
  Eigen::Matrix4d projection;
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column)
      projection(row, column) = vtkProjection->GetElement(row, column);
  const Eigen::Vector4d clip = projection * world.homogeneous();
  const Eigen::Vector2d ndc = clip.head<2>() / clip.w();  // -1..1, y up
  return {(ndc.x() + 1.0) / 2.0 * viewport.width(), (1.0 - ndc.y()) / 2.0 * viewport.height()};
}

class StudioWindow : public ::testing::Test
{
protected:
  void SetUp() override
  {
    window = test::openSampleWindow(1280, 800);
    ASSERT_NE(window, nullptr);
  }

  /// The 3D view as the committed baseline MarkerView3d.png shows it: 480 × 360 at frame 999 with
  /// section5-1 selected (labelled, with its trail), the camera reset.
  QImage renderBaselineView() const
  {
    ui::VtkViewport* viewport = window->markerView()->viewport();
    window->selectLabels({QStringLiteral("section5-1")});
    window->document().setCurrentFrame(999);
    viewport->setFixedSize(480, 360);
    window->markerView()->resetCamera();
    QTest::qWait(200);
    return viewport->grabFramebuffer();
  }

  /// Linear interpolation across every interior gap of `marker`, as one undoable command.
  std::vector<SamplePatch> linearFill(Eigen::Index marker) const
  {
    const Take& take = window->document().take();
    std::vector<SamplePatch> patches;
    for (const Gap& gap : findGaps(take.valid().col(marker), marker)) {
      if (gap.atEdge)
        continue;
      const Eigen::Vector3d a = take.position(gap.firstFrame - 1, marker);
      const Eigen::Vector3d b = take.position(gap.firstFrame + gap.length, marker);
      std::vector<Eigen::Index> frames;
      Eigen::Matrix<double, Eigen::Dynamic, 3> positions(gap.length, 3);
      for (Eigen::Index i = 0; i < gap.length; ++i) {
        frames.push_back(gap.firstFrame + i);
        const double t = static_cast<double>(i + 1) / static_cast<double>(gap.length + 1);
        positions.row(i) = ((1.0 - t) * a + t * b).transpose();
      }
      patches.push_back(makePatch(marker, std::move(frames), std::move(positions), SampleOrigin::Filled));
    }
    return patches;
  }

  std::unique_ptr<MainWindow> window;
};

TEST_F(StudioWindow, OpensTheSampleIntoTheTable)
{
  EXPECT_EQ(window->markerTable()->model()->rowCount(), 38);
  EXPECT_EQ(window->document().take().frameCount(), 3000);
  EXPECT_FALSE(window->isWindowModified());
}

TEST_F(StudioWindow, TableSelectionReachesTheDocumentAndBack)
{
  QTableView* table = window->markerTable();
  const QModelIndex row = table->model()->index(10, 0);  // section3-1 in file order
  table->selectionModel()->select(row, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
  ASSERT_EQ(window->document().selection().size(), 1u);
  EXPECT_EQ(window->document().take().label(window->document().selection().front()), "section3-1");
  window->selectLabels({QStringLiteral("root-2"), QStringLiteral("section14-2")});
  const auto selected = table->selectionModel()->selectedRows();
  ASSERT_EQ(selected.size(), 2);
  EXPECT_EQ(selected[0].data().toString() + "," + selected[1].data().toString(), "root-2,section14-2");
  // The status line names the selection as soon as it changes, not at the next frame.
  auto* status = window->findChild<QLabel*>(QStringLiteral("frameStatus"));
  ASSERT_NE(status, nullptr);
  EXPECT_TRUE(status->text().contains(QStringLiteral("2 markers selected"))) << status->text().toStdString();
}

TEST_F(StudioWindow, TheStatusLineNamesTheFrameWithinTheTakesOwnNumbering)
{
  Take take = window->document().take();
  take.setFirstFrame(63);  // a trimmed take: its frames are numbered 63…3062
  test::TempDir dir;
  writeC3d(take, dir.file("trimmed.c3d"));
  ASSERT_EQ(window->openFile(QString::fromStdString(dir.file("trimmed.c3d").string()), true), QString());
  window->document().setCurrentFrame(take.frameCount() - 1);
  auto* status = window->findChild<QLabel*>(QStringLiteral("frameStatus"));
  ASSERT_NE(status, nullptr);
  // Not "Frame 3062 of 3000": the frame number and the take's range in the same numbering.
  EXPECT_TRUE(status->text().startsWith(QStringLiteral("Frame 3062 of 63–3062"))) << status->text().toStdString();
}

TEST_F(StudioWindow, FillChangesOnlyTheGapAndUndoRestoresBitForBit)
{
  TakeDocument& doc = window->document();
  const Take before = doc.take();
  const Eigen::Index marker = *before.markerIndex("section4-2");
  doc.undoStack()->push(new ui::ApplyPatchesCommand(doc, linearFill(marker), QStringLiteral("Fill gaps")));
  EXPECT_TRUE(window->isWindowModified());
  const Take& after = doc.take();
  for (Eigen::Index m = 0; m < before.markerCount(); ++m)
    for (Eigen::Index f = 0; f < before.frameCount(); ++f) {
      const bool wasGap = m == marker && !before.isValid(f, m) && f > 0 && f < before.frameCount() - 1;
      if (wasGap) {
        ASSERT_TRUE(after.isValid(f, m)) << f;
        ASSERT_EQ(after.state(f, m), SampleOrigin::Filled);
      } else {
        ASSERT_EQ(after.isValid(f, m), before.isValid(f, m)) << m << " " << f;
        if (before.isValid(f, m)) {
          ASSERT_EQ(after.position(f, m), before.position(f, m));
        }
      }
    }
  doc.undoStack()->undo();
  EXPECT_TRUE((doc.take().valid() == before.valid()).all());
  EXPECT_TRUE((doc.take().residuals() == before.residuals()).all());
  EXPECT_TRUE((doc.take().states() == before.states()).all());
  for (Eigen::Index f = 0; f < before.frameCount(); ++f)
    ASSERT_EQ(doc.take().position(f, marker), before.position(f, marker));
  EXPECT_FALSE(window->isWindowModified());
  doc.undoStack()->redo();
  EXPECT_TRUE(doc.take().valid().col(marker).segment(1105, 60).all());
}

TEST_F(StudioWindow, FillingOnlyTheSelectedRangeLeavesTheRestOfTheGap)
{
  TakeDocument& doc = window->document();
  const Take before = doc.take();
  const Eigen::Index marker = *before.markerIndex("section4-2");  // a gap over frames 1105–1164
  ui::CleaningPanel* panel = window->cleaningPanel();
  auto* step = panel->step<ui::GapFillStep>();
  ASSERT_NE(step, nullptr);
  panel->setCurrentStep(step);
  step->setMaxGapSeconds(1.0);  // the 60-frame gap is longer than the 0.5 s default
  auto* rangeOnly = panel->findChild<QCheckBox*>(QStringLiteral("rangeOnly"));
  ASSERT_NE(rangeOnly, nullptr);
  rangeOnly->setChecked(true);
  doc.setRange(1100, 1130);
  test::waitForPreview(*panel);
  ASSERT_GT(panel->apply(), 0) << panel->lastResult().summary.toStdString();
  const Take& after = doc.take();
  EXPECT_TRUE(after.valid().col(marker).segment(1105, 26).all());
  EXPECT_FALSE(after.valid().col(marker).segment(1131, 34).any()) << "frames outside the range stay a gap";
  for (Eigen::Index m = 0; m < before.markerCount(); ++m)
    for (Eigen::Index f = 0; f < before.frameCount(); ++f) {
      if (f < 1100 || f > 1130) {
        ASSERT_EQ(after.isValid(f, m), before.isValid(f, m)) << m << " " << f;
      }
    }
  doc.clearRange();
  test::waitForPreview(*panel);
  EXPECT_TRUE(panel->lastResult().patches.empty()) << "no range selected: nothing to change";
}

TEST_F(StudioWindow, SaveAndReopenKeepTheEdit)
{
  TakeDocument& doc = window->document();
  const Eigen::Index marker = *doc.take().markerIndex("section3-1");
  doc.undoStack()->push(new ui::ApplyPatchesCommand(doc, linearFill(marker), QStringLiteral("Fill gaps")));
  test::TempDir dir;
  const QString path = QString::fromStdString(dir.file("edited.c3d").string());
  ASSERT_EQ(doc.save(path), QString());
  EXPECT_FALSE(window->isWindowModified());
  const Take saved = doc.take();
  ASSERT_EQ(window->openFile(path, true), QString());
  EXPECT_TRUE((doc.take().valid() == saved.valid()).all());
  // C3D stores floats: the filled doubles come back to float precision.
  EXPECT_LT((doc.take().position(900, marker) - saved.position(900, marker)).norm(), 1e-4);
  // The provenance survives: the filled samples reopen as filled, the rest as measured.
  ASSERT_EQ(saved.state(900, marker), SampleOrigin::Filled);
  EXPECT_TRUE((doc.take().states() == saved.states()).all());
  EXPECT_EQ(doc.take().state(900, marker), saved.state(900, marker));
}

TEST_F(StudioWindow, CorruptFileShowsAnErrorAndKeepsTheOpenTake)
{
  const test::TempDir dir;
  test::writeCorruptC3d(dir.file("corrupt.c3d"));
  const QString error = window->openFile(QString::fromStdString(dir.file("corrupt.c3d").string()), true);
  EXPECT_TRUE(error.contains(QStringLiteral("parameter section corrupt"))) << error.toStdString();
  EXPECT_EQ(window->document().take().frameCount(), 3000);
  EXPECT_EQ(window->document().take().label(0), "root-1");
}

TEST_F(StudioWindow, RenamingInTheTableIsUndoable)
{
  QAbstractItemModel* model = window->markerTable()->model();
  const QModelIndex cell = model->index(0, 0);
  EXPECT_FALSE(model->setData(cell, QStringLiteral("root-2"))) << "duplicate labels are refused";
  ASSERT_TRUE(model->setData(cell, QStringLiteral("head front")));
  EXPECT_EQ(window->document().take().label(0), "head front");
  EXPECT_EQ(model->data(cell).toString(), QStringLiteral("head front"));
  window->document().undoStack()->undo();
  EXPECT_EQ(window->document().take().label(0), "root-1");
}

TEST_F(StudioWindow, DeleteRangeMakesAGapForTheSelectedMarkers)
{
  ASSERT_TRUE(QTest::qWaitForWindowActive(window.get())) << "the Delete shortcut needs the active window";
  TakeDocument& doc = window->document();
  window->selectLabels({QStringLiteral("root-1"), QStringLiteral("root-3")});
  doc.setRange(100, 149);
  QTest::keyClick(window.get(), Qt::Key_Delete);
  for (const char* label : {"root-1", "root-3"}) {
    const Eigen::Index m = *doc.take().markerIndex(label);
    EXPECT_FALSE(doc.take().valid().col(m).segment(100, 50).any()) << label;
    EXPECT_TRUE(doc.take().isValid(99, m) && doc.take().isValid(150, m)) << label;
  }
  EXPECT_TRUE(doc.take().valid().col(1).all()) << "root-2 was not selected";
  doc.undoStack()->undo();
  EXPECT_TRUE(doc.take().valid().col(0).all());
}

TEST_F(StudioWindow, DeletingMarkersUpdatesTheTableAndUndoRestoresThemBitForBit)
{
  ASSERT_TRUE(QTest::qWaitForWindowActive(window.get())) << "the shortcut needs the active window";
  TakeDocument& doc = window->document();
  const Take original = doc.take();
  window->selectLabels({QStringLiteral("section4-1"), QStringLiteral("root-2")});
  QTest::keyClick(window.get(), Qt::Key_Delete, Qt::ControlModifier);
  EXPECT_EQ(doc.take().markerCount(), original.markerCount() - 2);
  EXPECT_FALSE(doc.take().markerIndex("section4-1"));
  EXPECT_EQ(window->markerTable()->model()->rowCount(), original.markerCount() - 2);
  EXPECT_TRUE(doc.selection().empty());
  doc.undoStack()->undo();
  ASSERT_EQ(doc.take().labels(), original.labels());
  EXPECT_TRUE((doc.take().valid() == original.valid()).all());
  EXPECT_TRUE((doc.take().states() == original.states()).all());
  for (Eigen::Index m = 0; m < original.markerCount(); ++m)
    ASSERT_TRUE(doc.take().trajectory(m).cwiseEqual(original.trajectory(m)).all() ||
                !original.valid().col(m).all())
        << original.label(m);
  EXPECT_EQ(window->markerTable()->model()->rowCount(), original.markerCount());
}

TEST_F(StudioWindow, SwapOverRangeAndHideAreMenuActions)
{
  TakeDocument& doc = window->document();
  const Take original = doc.take();
  window->selectLabels({QStringLiteral("root-1"), QStringLiteral("root-2")});
  doc.setRange(10, 19);
  QAction* swap = nullptr;
  QAction* hide = nullptr;
  for (QAction* action : window->findChildren<QAction*>()) {
    if (action->text() == QStringLiteral("&Swap Over Range"))
      swap = action;
    if (action->text() == QStringLiteral("&Hide Selected"))
      hide = action;
  }
  ASSERT_NE(swap, nullptr);
  ASSERT_NE(hide, nullptr);
  swap->trigger();
  EXPECT_EQ(doc.take().position(15, 0), original.position(15, 1));
  EXPECT_EQ(doc.take().position(15, 1), original.position(15, 0));
  EXPECT_EQ(doc.take().position(20, 0), original.position(20, 0));
  doc.undoStack()->undo();
  EXPECT_EQ(doc.take().position(15, 0), original.position(15, 0));
  hide->trigger();
  EXPECT_TRUE(doc.isHidden(0) && doc.isHidden(1));
  EXPECT_FALSE(doc.isHidden(2));
  EXPECT_FALSE(doc.isModified()) << "hiding is a view setting, not an edit";
  doc.showAllMarkers();
  EXPECT_EQ(doc.hiddenCount(), 0);
}

TEST_F(StudioWindow, DraggingASampleOnTheCurvesEditsOneCoordinateUndoably)
{
  TakeDocument& doc = window->document();
  const Take original = doc.take();
  const Eigen::Index marker = *doc.take().markerIndex("section7-1");
  window->selectLabels({QStringLiteral("section7-1")});
  ui::CurveView* curves = window->curveView();
  curves->setVisibleRange(500, 540);
  // The dock may not be exposed yet right after the window shows: paint until it has drawn.
  ASSERT_TRUE(QTest::qWaitFor([&] {
    curves->repaint();
    return curves->pointOf(marker, 520, 2).has_value();
  }, 3000));
  const auto point = curves->pointOf(marker, 520, 2);
  const QPoint start = point->toPoint();
  QTest::mousePress(curves, Qt::LeftButton, Qt::NoModifier, start);
  QMouseEvent move(QEvent::MouseMove, QPointF(start + QPoint(0, -20)), curves->mapToGlobal(QPointF(start)),
                   Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(curves, &move);
  EXPECT_EQ(doc.preview().size(), 1u) << "the drag is previewed";
  EXPECT_EQ(doc.take().position(520, marker), original.position(520, marker)) << "not applied while dragging";
  QTest::mouseRelease(curves, Qt::LeftButton, Qt::NoModifier, start + QPoint(0, -20));
  const Eigen::Vector3d edited = doc.take().position(520, marker);
  EXPECT_GT(edited.z(), original.position(520, marker).z()) << "dragged up: z grew";
  EXPECT_EQ(edited.x(), original.position(520, marker).x());
  EXPECT_EQ(edited.y(), original.position(520, marker).y());
  EXPECT_EQ(doc.take().state(520, marker), SampleOrigin::Edited);
  EXPECT_EQ(doc.take().position(519, marker), original.position(519, marker));
  EXPECT_TRUE(doc.preview().empty());
  doc.undoStack()->undo();
  EXPECT_EQ(doc.take().position(520, marker), original.position(520, marker));
  EXPECT_EQ(doc.take().state(520, marker), original.state(520, marker));
}

TEST_F(StudioWindow, HeadStabilizedViewHoldsTheHeadMarkersStillWithoutTouchingTheTake)
{
  TakeDocument& doc = window->document();
  const Take original = doc.take();
  ui::MarkerView3d* view = window->markerView();
  std::vector<Eigen::Index> roots;
  for (const char* label : {"root-1", "root-2", "root-3", "root-4", "root-5", "root-6"})
    roots.push_back(*doc.take().markerIndex(label));
  ASSERT_EQ(view->setHeadReference(roots), QString());
  // The head moves 20-30 mm over the take; stabilized, its markers stay within the rigid body's
  // own jitter (about 2 mm).
  const Eigen::Index root = roots.front();
  double labSpread = 0.0, stableSpread = 0.0;
  for (Eigen::Index f = 0; f < doc.take().frameCount(); f += 50) {
    labSpread = std::max(labSpread, (doc.take().position(f, root) - doc.take().position(0, root)).norm());
    stableSpread = std::max(stableSpread, (view->displayPosition(f, root) - view->displayPosition(0, root)).norm());
  }
  EXPECT_GT(labSpread, 20.0);
  EXPECT_LT(stableSpread, 3.0);
  EXPECT_EQ(doc.take().position(500, root), original.position(500, root)) << "a view setting, not an edit";
  EXPECT_FALSE(view->setHeadReference({roots[0], roots[1]}).isEmpty()) << "two markers cannot carry a pose";
  EXPECT_EQ(view->headReference().size(), 6u) << "a refused reference leaves the view as it was";
  ASSERT_EQ(view->setHeadReference({}), QString());
  EXPECT_EQ(view->displayPosition(500, root), original.position(500, root));
}

TEST_F(StudioWindow, StabilizeHeadStepMovesTheTakeIntoTheHeadFrameUndoably)
{
  TakeDocument& doc = window->document();
  const Take original = doc.take();
  ui::CleaningPanel* panel = window->cleaningPanel();
  auto* step = panel->step<ui::HeadStabilizationStep>();
  ASSERT_NE(step, nullptr);
  panel->setCurrentStep(step);
  test::waitForPreview(*panel);
  EXPECT_EQ(doc.take().position(500, 0), original.position(500, 0)) << "a preview never touches the take";
  ASSERT_GT(panel->apply(), 0) << panel->lastResult().summary.toStdString();
  // The reference markers (guessed from their root-N labels) now hold still.
  const Eigen::Index root = *doc.take().markerIndex("root-1");
  double spread = 0.0;
  for (Eigen::Index f = 0; f < doc.take().frameCount(); f += 50)
    spread = std::max(spread, (doc.take().position(f, root) - doc.take().position(0, root)).norm());
  EXPECT_LT(spread, 3.0);
  EXPECT_TRUE((doc.take().valid() == original.valid()).all());
  doc.undoStack()->undo();
  for (Eigen::Index m = 0; m < original.markerCount(); ++m)
    ASSERT_TRUE(doc.take().trajectory(m) == original.trajectory(m)) << "undo restores bit for bit";
  // The take's reference markers are what the step uses: two cannot carry a head pose.
  doc.undoStack()->push(new ui::SetReferenceMarkersCommand(
      doc, {*doc.take().markerIndex("root-1"), *doc.take().markerIndex("root-3")}));
  test::waitForPreview(*panel);
  EXPECT_TRUE(panel->lastResult().summary.contains(QStringLiteral("three"))) << panel->lastResult().summary.toStdString();
  EXPECT_TRUE(panel->lastResult().patches.empty());
}

TEST_F(StudioWindow, AWindowScreenshotShowsThe3DViewsScene)
{
  // --screenshot grabs the whole window; the 3D view is a native OpenGL window that a plain
  // QWidget::grab leaves blank, so grabWithViewports draws its scene in.
  ui::VtkViewport* viewport = window->markerView()->viewport();
  ASSERT_TRUE(viewport->usable());
  const QImage scene = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
  const QRect area(viewport->mapTo(window.get(), QPoint(0, 0)), viewport->size());
  const QImage shot = ui::grabWithViewports(*window).convertToFormat(QImage::Format_RGB32);
  EXPECT_TRUE(test::compareImages(shot.copy(area), scene).matches());
  EXPECT_FALSE(test::compareImages(window->grab().toImage().convertToFormat(QImage::Format_RGB32).copy(area), scene)
                   .matches())
      << "a plain grab shows the scene after all: the helper is not needed";
}

TEST_F(StudioWindow, RubberBandSelectsTheMarkersInsideIt)
{
  TakeDocument& doc = window->document();
  ui::MarkerView3d* view = window->markerView();
  view->viewport()->repaint();
  QApplication::processEvents();
  ASSERT_TRUE(view->headReference().empty()) << "the markers are drawn where the take has them";
  // The expected selection from the markers' positions projected here, not from the view.
  const Take& take = doc.take();
  const Eigen::Index frame = doc.currentFrame();
  std::vector<std::pair<Eigen::Index, QPointF>> drawn;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    if (take.isValid(frame, m) && !doc.isHidden(m))
      drawn.emplace_back(m, projectThroughCamera(*view->viewport(), take.position(frame, m)));
  const Eigen::Index a = *take.markerIndex("section13-1");
  const Eigen::Index b = *take.markerIndex("section14-1");
  const auto where = [&](Eigen::Index marker) {
    return std::find_if(drawn.begin(), drawn.end(), [&](const auto& d) { return d.first == marker; })->second;
  };
  ASSERT_TRUE(take.isValid(frame, a) && take.isValid(frame, b));
  const QRect band = QRectF(where(a), where(b)).normalized().adjusted(-3, -3, 3, 3).toRect();
  std::vector<Eigen::Index> inside;
  for (const auto& [marker, position] : drawn)
    if (QRectF(band).contains(position))
      inside.push_back(marker);
  ASSERT_GE(inside.size(), 2u);
  EXPECT_LT(inside.size(), drawn.size()) << "the band leaves some drawn markers out";
  QWidget* viewport = view->viewport();
  QTest::mousePress(viewport, Qt::LeftButton, Qt::ControlModifier, band.topLeft());
  QMouseEvent move(QEvent::MouseMove, QPointF(band.bottomRight()), viewport->mapToGlobal(QPointF(band.bottomRight())),
                   Qt::NoButton, Qt::LeftButton, Qt::ControlModifier);
  QApplication::sendEvent(viewport, &move);
  // The band is drawn over the scene on the screen (no widget shows above the native window):
  // its top edge is a light line across the band.
  const QRect topEdge(band.left(), band.top(), band.width(), 1);
  qsizetype lit = 0;
  QElapsedTimer clock;
  clock.start();
  while ((lit = test::pixelsNear(test::shownOnScreen(*viewport, topEdge), QColor(242, 242, 242), 16)) <
             band.width() * 9 / 10 &&
         clock.elapsed() < 3000)
    QTest::qWait(20);
  EXPECT_GE(lit, band.width() * 9 / 10) << "the rubber band is not on the screen";
  QTest::mouseRelease(viewport, Qt::LeftButton, Qt::ControlModifier, band.bottomRight());
  EXPECT_EQ(doc.selection(), inside);
  EXPECT_TRUE(std::find(inside.begin(), inside.end(), a) != inside.end());
  EXPECT_TRUE(std::find(inside.begin(), inside.end(), b) != inside.end());
}

TEST_F(StudioWindow, MarkerLinksJoinNeighboursOfTheFace)
{
  ui::MarkerView3d* view = window->markerView();
  view->setLinksVisible(true);
  const Take& take = window->document().take();
  ASSERT_GE(view->links().size(), static_cast<std::size_t>(take.markerCount()));
  // Neighbours on a face about 250 mm tall are a few centimetres apart, and every face marker is
  // joined to some other.
  const Eigen::Index frame = mostCompleteFrame(take);
  std::vector<bool> linked(static_cast<std::size_t>(take.markerCount()), false);
  for (const auto& [a, b] : view->links()) {
    EXPECT_LT((take.position(frame, a) - take.position(frame, b)).norm(), 80.0) << take.label(a) << "-" << take.label(b);
    linked[static_cast<std::size_t>(a)] = linked[static_cast<std::size_t>(b)] = true;
  }
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    if (take.label(m).rfind("section", 0) == 0 && take.isValid(frame, m)) {
      EXPECT_TRUE(linked[static_cast<std::size_t>(m)]) << take.label(m);
    }
  view->setLinksVisible(false);
}

TEST_F(StudioWindow, TimelineJumpsBetweenFlaggedSamples)
{
  TakeDocument& doc = window->document();
  doc.setFlags({{3, 700}, {5, 250}, {3, 1200}});
  doc.setCurrentFrame(300);
  window->timeline()->jumpToFlag(1);
  EXPECT_EQ(doc.currentFrame(), 700);
  window->timeline()->jumpToFlag(-1);
  EXPECT_EQ(doc.currentFrame(), 250);
  doc.setSelection({3});
  window->timeline()->jumpToFlag(1);
  EXPECT_EQ(doc.currentFrame(), 700) << "only the selected marker's flags";
  window->timeline()->jumpToFlag(1);
  EXPECT_EQ(doc.currentFrame(), 1200);
  window->timeline()->jumpToFlag(1);
  EXPECT_EQ(doc.currentFrame(), 1200) << "no flag after the last one: stay";
}

TEST_F(StudioWindow, TheTableCountsBadPointsUnderReview)
{
  TakeDocument& doc = window->document();
  doc.setFlags({{2, 10}, {2, 20}, {7, 30}});
  QAbstractItemModel* model = window->markerTable()->model();
  auto badPoints = [&](Eigen::Index marker) {
    for (int row = 0; row < model->rowCount(); ++row)
      if (model->index(row, ui::MarkerTableModel::LabelColumn).data().toString() ==
          QString::fromStdString(doc.take().label(marker)))
        return model->index(row, ui::MarkerTableModel::BadPointsColumn).data().toInt();
    return -1;
  };
  EXPECT_EQ(badPoints(2), 2);
  EXPECT_EQ(badPoints(7), 1);
  EXPECT_EQ(badPoints(3), 0);
  doc.setFlags({});
  EXPECT_EQ(badPoints(2), 0);
}

TEST_F(StudioWindow, HoveringAMarkerShowsItsLabel)
{
  TakeDocument& doc = window->document();
  ui::MarkerView3d* view = window->markerView();
  view->viewport()->repaint();
  QApplication::processEvents();
  const Eigen::Index marker = *doc.take().markerIndex("section7-1");
  const auto position = view->screenPosition(marker);
  ASSERT_TRUE(position.has_value());
  QWidget* viewport = view->viewport();
  QMouseEvent move(QEvent::MouseMove, *position, viewport->mapToGlobal(*position), Qt::NoButton, Qt::NoButton,
                   Qt::NoModifier);
  QApplication::sendEvent(viewport, &move);
  EXPECT_TRUE(QToolTip::text().startsWith(QStringLiteral("section7-1"))) << QToolTip::text().toStdString();
  QToolTip::hideText();
}

/// Cuts frames [0, 99] of `label` out into an unlabelled fragment marker "Unlabeled2" (as a
/// capture system leaves a marker it lost track of), in one undoable step per part.
Eigen::Index cutIntoFragment(TakeDocument& doc, const std::string& label)
{
  const Eigen::Index marker = *doc.take().markerIndex(label);
  MarkerColumn fragment = doc.take().column(marker);
  fragment.label = "Unlabeled2";
  fragment.valid.tail(fragment.valid.size() - 100).setConstant(false);
  doc.undoStack()->push(new ui::InsertMarkerCommand(doc, std::move(fragment), QStringLiteral("fragment")));
  doc.undoStack()->push(new ui::ApplyPatchesCommand(doc, {deleteSamples(doc.take(), marker, 0, 99)}, QStringLiteral("cut")));
  return doc.take().markerCount() - 1;
}

TEST_F(StudioWindow, ClickingAPointInLabellingModeGivesItTheSelectedLabel)
{
  TakeDocument& doc = window->document();
  const Take original = doc.take();
  const Eigen::Index fragment = cutIntoFragment(doc, "section7-1");
  const Eigen::Index marker = *doc.take().markerIndex("section7-1");
  EXPECT_FALSE(doc.take().valid().col(marker).head(100).any());
  window->selectLabels({QStringLiteral("section7-1")});
  emit window->markerView()->labelPointClicked(fragment);
  EXPECT_EQ(doc.take().markerCount(), original.markerCount()) << "the fragment joined its marker";
  EXPECT_TRUE(doc.take().valid().col(marker).head(100).all());
  EXPECT_EQ(doc.take().position(50, marker), original.position(50, marker));
  doc.undoStack()->undo();
  EXPECT_EQ(doc.take().markerCount(), original.markerCount() + 1);
  EXPECT_EQ(doc.take().label(fragment), "Unlabeled2");
  EXPECT_FALSE(doc.take().valid().col(marker).head(100).any());
}

TEST_F(StudioWindow, TrackAndLabelJoinsAFragmentBackAndUndoes)
{
  TakeDocument& doc = window->document();
  const Take original = doc.take();
  cutIntoFragment(doc, "section7-1");
  const Eigen::Index withFragment = doc.take().markerCount();
  QAction* track = nullptr;
  for (QAction* action : window->findChildren<QAction*>())
    if (action->text() == QStringLiteral("&Track and Label"))
      track = action;
  ASSERT_NE(track, nullptr);
  track->trigger();
  const Eigen::Index marker = *doc.take().markerIndex("section7-1");
  EXPECT_GT(doc.take().valid().col(marker).head(100).count(), 90) << "the fragment got its label back";
  EXPECT_NEAR((doc.take().position(50, marker) - original.position(50, marker)).norm(), 0.0, 1e-9);
  doc.undoStack()->undo();
  EXPECT_EQ(doc.take().markerCount(), withFragment);
  EXPECT_FALSE(doc.take().valid().col(*doc.take().markerIndex("section7-1")).head(100).any());
}

TEST_F(StudioWindow, SwapReviewReturnsOnlyTheAcceptedSwaps)
{
  const Take& take = window->document().take();
  std::vector<LabelSwap> swaps(3);
  for (std::size_t i = 0; i < swaps.size(); ++i)
    swaps[i] = LabelSwap{static_cast<Eigen::Index>(100 * (i + 1)), 1, 2, 40.0, 1.0};
  ui::SwapReviewDialog dialog(take, swaps);
  auto* list = dialog.findChild<QListWidget*>();
  ASSERT_NE(list, nullptr);
  ASSERT_EQ(list->count(), 3);
  EXPECT_TRUE(list->item(0)->text().contains(QStringLiteral("root-2")));
  list->item(1)->setCheckState(Qt::Unchecked);
  const auto accepted = dialog.acceptedSwaps();
  ASSERT_EQ(accepted.size(), 2u);
  EXPECT_EQ(accepted[0].frame, 100);
  EXPECT_EQ(accepted[1].frame, 300);
  Eigen::Index requested = -1;
  QObject::connect(&dialog, &ui::SwapReviewDialog::frameRequested, [&](Eigen::Index f) { requested = f; });
  emit list->itemDoubleClicked(list->item(2));
  EXPECT_EQ(requested, 300);
}

TEST_F(StudioWindow, SpikePreviewLeavesTheTakeAloneAndApplyIsUndoable)
{
  TakeDocument& doc = window->document();
  // Put a 6 mm spike into a clean stretch, as the file's own (undoable) edit.
  const Eigen::Index marker = *doc.take().markerIndex("section8-1");
  const Eigen::Vector3d truth = doc.take().position(1500, marker);
  doc.undoStack()->push(new ui::ApplyPatchesCommand(
      doc, {makePatch(marker, {1500}, (truth + Eigen::Vector3d(6.0, 0.0, 0.0)).transpose(), SampleOrigin::Edited)},
      QStringLiteral("spike")));
  const Take before = doc.take();
  ui::CleaningPanel* panel = window->cleaningPanel();
  test::waitForPreview(*panel);
  const auto& flags = doc.flags();
  EXPECT_NE(std::find(flags.begin(), flags.end(), std::make_pair(marker, Eigen::Index{1500})), flags.end());
  EXPECT_FALSE(doc.preview().empty());
  EXPECT_EQ(doc.take().position(1500, marker), before.position(1500, marker)) << "a preview never touches the take";
  EXPECT_GT(panel->apply(), 0);
  EXPECT_LT((doc.take().position(1500, marker) - truth).norm(), 1.0) << "the spike is replaced by its neighbours";
  EXPECT_EQ(doc.take().state(1500, marker), SampleOrigin::Edited);
  EXPECT_TRUE(doc.preview().empty());
  doc.undoStack()->undo();
  EXPECT_EQ(doc.take().position(1500, marker), before.position(1500, marker));
}

TEST(StudioLanguage, GermanAndChineseAreBuiltInAndComplete)
{
  auto& app = *QCoreApplication::instance();
  ASSERT_TRUE(studio::installLanguage(app, QStringLiteral("de")));
  EXPECT_EQ(QCoreApplication::translate("mocap::studio::MainWindow", "&File"), QStringLiteral("&Datei"));
  EXPECT_EQ(QCoreApplication::translate("SpikeStep", "%n bad point(s) found", nullptr, 2),
            QStringLiteral("2 Ausreißer gefunden"));
  ASSERT_TRUE(studio::installLanguage(app, QStringLiteral("zh_CN")));
  EXPECT_EQ(QCoreApplication::translate("mocap::studio::MainWindow", "&File"), QStringLiteral("文件(&F)"));
  EXPECT_FALSE(studio::installLanguage(app, QStringLiteral("xx")));
  ASSERT_TRUE(studio::installLanguage(app, QStringLiteral("en")));
  EXPECT_EQ(QCoreApplication::translate("mocap::studio::MainWindow", "&File"), QStringLiteral("&File"));
}

TEST(StudioLanguage, QtsOwnButtonsSpeakTheChosenLanguage)
{
  const QString catalogue = QLibraryInfo::path(QLibraryInfo::TranslationsPath) + QStringLiteral("/qtbase_de.qm");
  if (!QFileInfo::exists(catalogue))
    GTEST_SKIP() << "Qt's own catalogue " << catalogue.toStdString()
                 << " is missing (apt-get install qt6-translations-l10n; scripts/setup.sh installs it)";
  auto& app = *QCoreApplication::instance();
  ASSERT_TRUE(studio::installLanguage(app, QStringLiteral("de")));
  const QDialogButtonBox german(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  EXPECT_EQ(german.button(QDialogButtonBox::Cancel)->text().remove(QLatin1Char('&')), QStringLiteral("Abbrechen"));
  ASSERT_TRUE(studio::installLanguage(app, QStringLiteral("en")));
  const QDialogButtonBox english(QDialogButtonBox::Cancel);
  EXPECT_EQ(english.button(QDialogButtonBox::Cancel)->text().remove(QLatin1Char('&')), QStringLiteral("Cancel"));
}

TEST_F(StudioWindow, ChangedColoursReachTheViewport)
{
  ui::VtkViewport* viewport = window->markerView()->viewport();
  ASSERT_TRUE(viewport->usable()) << viewport->failureReason().toStdString();
  const ui::ColorScheme defaults;
  ui::ColorScheme red;
  red.background = QColor(220, 20, 20);
  ui::setColorScheme(red);
  window->markerView()->refreshColors();
  QTest::qWait(200);
  const QImage image = viewport->grabFramebuffer();
  ui::setColorScheme(defaults);
  window->markerView()->refreshColors();
  ASSERT_FALSE(image.isNull());
  const QColor corner = image.pixelColor(2, image.height() - 3);  // bottom: the chosen colour itself
  EXPECT_GT(corner.red(), 180);
  EXPECT_LT(corner.green(), 60);
}

// Under a CPU rasterizer, frame changes in quick succession render without the FXAA pass (a third
// of a frame's time there), the view is redone antialiased once they pause, and a grab is always
// antialiased: it matches the settled view exactly.
TEST_F(StudioWindow, QuickFrameChangesSkipAntialiasingUntilTheySettle)
{
  ui::VtkViewport* viewport = window->markerView()->viewport();
  ASSERT_TRUE(viewport->usable()) << viewport->failureReason().toStdString();
  if (!viewport->softwareRendered())
    GTEST_SKIP() << "hardware rendering multisamples every frame";
  TakeDocument& doc = window->document();
  doc.setCurrentFrame(400);
  // (The window's first renders, as it lays out and its previews arrive, come in quick succession.)
  EXPECT_TRUE(QTest::qWaitFor([&] { return !viewport->lastRenderQuick(); }, 5000));
  int quick = 0;
  for (Eigen::Index f = 401; f <= 410; ++f) {
    doc.setCurrentFrame(f);
    QTest::qWait(16);
    quick += viewport->lastRenderQuick() ? 1 : 0;
  }
  EXPECT_GE(quick, 5) << "renders 16 ms apart skip the antialiasing";
  EXPECT_TRUE(viewport->lastRenderQuick());
  const QImage grabbed = viewport->grabFramebuffer();
  EXPECT_FALSE(viewport->lastRenderQuick()) << "a grab renders antialiased";
  QTest::qWait(ui::VtkViewport::kSettleMs + 150);
  doc.setCurrentFrame(411);
  QTest::qWait(16);
  doc.setCurrentFrame(410);
  QTest::qWait(16);
  EXPECT_TRUE(viewport->lastRenderQuick());
  EXPECT_TRUE(QTest::qWaitFor([&] { return !viewport->lastRenderQuick(); }, 2000))
      << "the pause brought the antialiased render";
  EXPECT_TRUE(test::compareImages(viewport->grabFramebuffer(), grabbed).matches());
}

TEST_F(StudioWindow, AFlaggedBadPointIsDrawnInTheFlagColour)
{
  ui::VtkViewport* viewport = window->markerView()->viewport();
  ASSERT_TRUE(viewport->usable()) << viewport->failureReason().toStdString();
  TakeDocument& doc = window->document();
  const Eigen::Index marker = *doc.take().markerIndex("section8-1");
  const Eigen::Vector3d truth = doc.take().position(1500, marker);
  doc.undoStack()->push(new ui::ApplyPatchesCommand(
      doc, {makePatch(marker, {1500}, (truth + Eigen::Vector3d(6.0, 0.0, 0.0)).transpose(), SampleOrigin::Edited)},
      QStringLiteral("spike")));
  test::waitForPreview(*window->cleaningPanel());
  doc.setCurrentFrame(1500);
  QTest::qWait(200);
  const auto where = window->markerView()->screenPosition(marker);
  ASSERT_TRUE(where);
  const QImage image = viewport->grabFramebuffer();
  const qreal ratio = image.devicePixelRatio();
  const QColor drawn = image.pixelColor(int(where->x() * ratio), int(where->y() * ratio));
  EXPECT_GT(drawn.red(), drawn.green() + 80) << drawn.name().toStdString();
  EXPECT_GT(drawn.red(), drawn.blue() + 80) << drawn.name().toStdString();
}

TEST_F(StudioWindow, ViewportRendersTheMarkersLikeTheBaseline)
{
  ui::VtkViewport* viewport = window->markerView()->viewport();
  ASSERT_TRUE(viewport->usable()) << viewport->failureReason().toStdString();
  const QImage image = renderBaselineView();
  ASSERT_FALSE(image.isNull());
  // Not blank: the spheres make the image vary well beyond the gradient background.
  double mean = 0.0, meanSquare = 0.0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const double v = qGray(image.pixel(x, y));
      mean += v;
      meanSquare += v * v;
    }
  const double n = image.width() * image.height();
  const double variance = meanSquare / n - (mean / n) * (mean / n);
  EXPECT_GT(variance, 150.0);
  EXPECT_TRUE(test::matchesBaseline(image, QStringLiteral("MarkerView3d")));
}

// The comparison can fail: deleting any one unselected marker (an undoable edit, re-rendered with
// the camera unchanged) changes the view around that marker's projected disc and nowhere else, by
// more than the comparison allows, against the same view and against the committed baseline; undo
// renders the view as it was.
TEST_F(StudioWindow, ErasingAnyOneMarkerFailsTheRenderComparison)
{
  ui::VtkViewport* viewport = window->markerView()->viewport();
  ASSERT_TRUE(viewport->usable()) << viewport->failureReason().toStdString();
  const QImage full = renderBaselineView();
  const QImage baseline(QString::fromUtf8(checkout::baselineDir()) + QStringLiteral("/MarkerView3d.png"));
  ASSERT_FALSE(baseline.isNull());
  TakeDocument& doc = window->document();
  const Eigen::Index frame = doc.currentFrame();
  const std::vector<Eigen::Index> selection = doc.selection();
  ASSERT_EQ(selection.size(), 1u);
  qsizetype fewest = full.width() * full.height();
  QImage hardest;  // the render whose erased marker changed the fewest pixels
  std::string hardestLabel;
  int erased = 0;
  for (Eigen::Index m = 0; m < doc.take().markerCount(); ++m) {
    if (!doc.take().isValid(frame, m) || m == selection.front())
      continue;
    const std::string label = doc.take().label(m);
    const QPointF centre = projectThroughCamera(*viewport, doc.take().position(frame, m));
    doc.undoStack()->push(new ui::RemoveMarkersCommand(doc, {m}));
    const QImage without = viewport->grabFramebuffer();
    doc.undoStack()->undo();
    const test::ImageDifference fromView = test::compareImages(without, full);
    EXPECT_FALSE(fromView.matches()) << label << ": only " << fromView.differing << " pixels differ";
    EXPECT_FALSE(test::compareImages(without, baseline).matches()) << label;
    // A marker disc is about 11 pixels across in this view.
    const QRectF disc(centre - QPointF(12.0, 12.0), QSizeF(24.0, 24.0));
    EXPECT_TRUE(disc.contains(QRectF(fromView.bounds)))
        << label << " at " << centre.x() << ", " << centre.y() << " but pixels differ within x " << fromView.bounds.left()
        << "–" << fromView.bounds.right() << ", y " << fromView.bounds.top() << "–" << fromView.bounds.bottom();
    if (fromView.differing < fewest) {
      fewest = fromView.differing;
      hardest = without;
      hardestLabel = label;
    }
    ++erased;
  }
  EXPECT_GE(erased, 30);
  EXPECT_EQ(doc.selection(), selection);
  const test::ImageDifference restored = test::compareImages(viewport->grabFramebuffer(), full);
  EXPECT_TRUE(restored.matches()) << restored.differing << " pixels differ after undo";
  // The failure names a diff image whose highlighted pixels are the differing ones.
  const QString name = QStringLiteral("MarkerView3d.erased");
  const ::testing::AssertionResult result = test::matchesImage(hardest, full, name);
  EXPECT_FALSE(result);
  EXPECT_NE(std::string(result.message()).find(test::differenceImagePath(name).toStdString()), std::string::npos)
      << result.message();
  const QImage diff(test::differenceImagePath(name));
  ASSERT_EQ(diff.size(), full.size());
  qsizetype highlighted = 0;
  for (int y = 0; y < diff.height(); ++y)
    for (int x = 0; x < diff.width(); ++x)
      highlighted += diff.pixel(x, y) == qRgb(255, 0, 255) ? 1 : 0;
  EXPECT_EQ(highlighted, fewest);
  std::cout << "[ measured ] erasing one of " << erased << " markers changes at least " << fewest << " pixels ("
            << hardestLabel << "); after undo " << restored.differing << " differ\n";
}

} // namespace
} // namespace mocap
