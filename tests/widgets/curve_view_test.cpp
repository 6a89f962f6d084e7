// The curve view as a technician reads it (ticks, range, read-out, colours, following the current
// frame), the 3D view's colours, follow-head camera and stabilized indicator, and the smoothing
// step's summary.
#include "../core/test_support.h"
#include "screen_pixels.h"

#include "document/take_document.h"
#include "main_window.h"
#include "panels/layout_planning_panel.h"
#include "panels/smoothing_step.h"
#include "views/axis_ticks.h"
#include "views/curve_view.h"
#include "views/display_units.h"
#include "views/marker_view_3d.h"
#include "views/sample_colors.h"
#include "views/selection_palette.h"

#include "mocap/cleaning/spike_detection.h"
#include "mocap/model/sample_patch.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QImage>
#include <QInputDialog>
#include <QPicture>
#include <QLabel>
#include <QSettings>
#include <QTest>
#include <QTimer>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace mocap {
namespace {

/// `markers` smooth trajectories over `frames` frames at 120 Hz, each with a gap every ~8 s.
Take syntheticTake(Eigen::Index frames, Eigen::Index markers)
{
  std::vector<std::string> labels;
  for (Eigen::Index m = 0; m < markers; ++m)
    labels.push_back("marker" + std::to_string(m));
  Take take(labels, frames, 120.0);
  take.setFirstFrame(1);
  for (Eigen::Index m = 0; m < markers; ++m)
    for (Eigen::Index f = 0; f < frames; ++f) {
      const double t = take.timeOf(f);
      take.setPosition(f, m, Eigen::Vector3d(10.0 * std::sin(t + static_cast<double>(m)), 5.0 * std::cos(2.0 * t),
                                             3.0 * t + 20.0 * static_cast<double>(m)));
      take.valid()(f, m) = (f % 997) > 40;
    }
  return take;
}

/// Paints `view` once into an image (the view keeps its scales from that paint).
void paintOnce(QWidget& view)
{
  QImage image(view.size(), QImage::Format_ARGB32_Premultiplied);
  view.render(&image);
}

TEST(AxisTicks, NiceValuesForZeroToThirtySevenMillimetres)
{
  const ui::AxisTicks few = ui::niceTicks(0.0, 37.0, 5);
  EXPECT_DOUBLE_EQ(few.step, 10.0);
  EXPECT_EQ(few.values, (std::vector<double>{0.0, 10.0, 20.0, 30.0}));
  EXPECT_EQ(few.decimals, 0);
  const ui::AxisTicks more = ui::niceTicks(0.0, 37.0, 8);
  EXPECT_DOUBLE_EQ(more.step, 5.0);
  EXPECT_EQ(more.values.size(), 8u);  // 0, 5, ..., 35
  EXPECT_DOUBLE_EQ(more.values.back(), 35.0);
  // A sub-millimetre range: ticks at hundredths, shown with two decimals, exact multiples.
  const ui::AxisTicks fine = ui::niceTicks(-0.013, 0.042, 6);
  EXPECT_DOUBLE_EQ(fine.step, 0.01);
  EXPECT_EQ(fine.decimals, 2);
  ASSERT_FALSE(fine.values.empty());
  EXPECT_DOUBLE_EQ(fine.values.front(), -0.01);
  EXPECT_DOUBLE_EQ(fine.values.back(), 0.04);
  EXPECT_TRUE(ui::niceTicks(1.0, 1.0, 5).values.empty());
}

TEST(CurveView, TheValueRangeHoldsAPreviewFarOutsideTheCurve)
{
  ui::TakeDocument doc;
  doc.setTake(syntheticTake(2000, 3));
  doc.setSelection({1});
  ui::CurveView view(doc);
  view.resize(900, 420);
  const auto before = view.valueRange(2);
  ASSERT_TRUE(before);
  ASSERT_LT(before->second, 200.0);  // z of marker 1 stays within 20..70 mm
  // A fill proposal 500 mm away, as a stabilization preview can be.
  doc.setPreview({makePatch(1, {600, 601, 602}, Eigen::Matrix<double, 3, 3>::Constant(500.0), SampleOrigin::Filled)});
  const auto after = view.valueRange(2);
  ASSERT_TRUE(after);
  EXPECT_GE(after->second, 500.0);
  EXPECT_LE(after->first, before->first + 1e-9);
  // A preview for a marker that is not selected is not drawn, so it does not stretch the range.
  doc.setPreview({makePatch(0, {600}, Eigen::Matrix<double, 1, 3>::Constant(500.0), SampleOrigin::Filled)});
  EXPECT_LT(view.valueRange(2)->second, 200.0);
}

TEST(CurveView, AFillThatWasSmoothedIsDrawnAndReadAsFilled)
{
  const SampleState filledSmoothed = SampleState(SampleOrigin::Filled).with(SampleOperation::Smoothed);
  EXPECT_EQ(ui::primaryMark(filledSmoothed), ui::SampleMark::Filled);
  EXPECT_EQ(ui::secondaryMark(filledSmoothed), ui::SampleMark::Smoothed);
  EXPECT_EQ(ui::stateColor(filledSmoothed), ui::colorScheme().filled);
  EXPECT_EQ(ui::primaryMark(SampleState().with(SampleOperation::Smoothed)), ui::SampleMark::Smoothed);
  EXPECT_EQ(ui::secondaryMark(SampleState().with(SampleOperation::Smoothed)), ui::SampleMark::None);
  EXPECT_EQ(ui::primaryMark(SampleState().with(SampleOperation::Stabilized)), ui::SampleMark::None);
  EXPECT_GT(ui::SampleMark::Filled, ui::SampleMark::Smoothed) << "where marks meet, the made origin wins";
  ui::TakeDocument doc;
  Take take = syntheticTake(2000, 3);
  for (Eigen::Index f = 440; f < 460; ++f)
    take.setState(f, 2, filledSmoothed);
  doc.setTake(std::move(take));
  doc.setSelection({2});
  ui::CurveView view(doc);
  view.resize(900, 420);
  view.setVisibleRange(400, 500);
  paintOnce(view);
  const auto point = view.pointOf(2, 450, 2);
  ASSERT_TRUE(point);
  EXPECT_TRUE(view.readoutAt(*point).contains(QStringLiteral("filled, smoothed"))) << view.readoutAt(*point).toStdString();
  const auto measured = view.pointOf(2, 420, 2);
  ASSERT_TRUE(measured);
  EXPECT_FALSE(view.readoutAt(*measured).contains(QStringLiteral("filled")));
}

TEST(CurveView, HoverReadOutNamesMarkerFrameAndValue)
{
  ui::TakeDocument doc;
  doc.setTake(syntheticTake(2000, 3));
  doc.setSelection({0, 2});
  ui::CurveView view(doc);
  view.resize(900, 420);
  view.setVisibleRange(400, 500);
  paintOnce(view);
  const auto point = view.pointOf(2, 450, 2);  // z: 20 mm apart from marker 0's
  ASSERT_TRUE(point);
  const QString text = view.readoutAt(*point);
  const Take& take = doc.take();
  EXPECT_TRUE(text.contains(QStringLiteral("marker2"))) << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("frame 451"))) << text.toStdString();  // file numbering
  const QString value = ui::formatLength(take.position(450, 2).z(), take.units(), LengthUnit::Millimetre);
  EXPECT_TRUE(text.contains(value + QStringLiteral(" mm"))) << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("3.750 s"))) << text.toStdString();  // 450 / 120 Hz
  // In centimetres the same sample reads a tenth.
  view.setDisplayUnit(LengthUnit::Centimetre);
  paintOnce(view);
  EXPECT_TRUE(view.readoutAt(*point).contains(
      ui::formatLength(take.position(450, 2).z(), take.units(), LengthUnit::Centimetre) + QStringLiteral(" cm")));
  EXPECT_TRUE(view.readoutAt(QPointF(2.0, 2.0)).isEmpty()) << "the margin holds no sample";
}

TEST(CurveView, SettingTheFrameOutsideTheViewCentresItAndKeepsTheZoom)
{
  ui::TakeDocument doc;
  doc.setTake(syntheticTake(3000, 2));
  doc.setSelection({0});
  ui::CurveView view(doc);
  view.resize(900, 420);
  view.setVisibleRange(100, 300);
  doc.setCurrentFrame(200);  // inside: nothing moves
  EXPECT_DOUBLE_EQ(view.firstVisible(), 100.0);
  doc.setCurrentFrame(2000);  // e.g. a click on a bad point in a list
  EXPECT_LE(view.firstVisible(), 2000.0);
  EXPECT_GE(view.lastVisible(), 2000.0);
  EXPECT_DOUBLE_EQ(view.lastVisible() - view.firstVisible(), 200.0);
  EXPECT_NEAR((view.firstVisible() + view.lastVisible()) / 2.0, 2000.0, 1e-9);
  doc.setCurrentFrame(2990);  // near the end: as close to the centre as the take allows
  EXPECT_GE(view.lastVisible(), 2990.0);
  EXPECT_DOUBLE_EQ(view.lastVisible() - view.firstVisible(), 200.0);
}

/// Bytes QPicture records for one paint of a 1600×400 curve view showing all `frames` frames of
/// three selected markers with a smoothing-like preview over every frame: a count of what was drawn
/// (points, lines, dots), whatever the machine's load. Its time is measured by curve_paint_bench.
qsizetype paintedBytes(Eigen::Index frames)
{
  ui::TakeDocument doc;
  doc.setTake(syntheticTake(frames, 6));
  doc.setSelection({0, 1, 2});
  std::vector<SamplePatch> preview;
  for (Eigen::Index m = 0; m < 3; ++m) {
    std::vector<Eigen::Index> rows;
    Eigen::Matrix<double, Eigen::Dynamic, 3> positions(frames, 3);
    for (Eigen::Index f = 0; f < frames; ++f) {
      rows.push_back(f);
      positions.row(f) = 1.01 * doc.take().position(f, m).transpose();
    }
    preview.push_back(makePatch(m, rows, positions, SampleState().with(SampleOperation::Smoothed)));
  }
  doc.setPreview(preview);
  ui::CurveView view(doc);
  view.resize(1600, 400);
  QPicture picture;
  view.render(&picture);
  return static_cast<qsizetype>(picture.size());
}

TEST(CurveView, PaintingTwentyThousandFramesDrawsNoMoreThanTwoThousand)
{
  // Ten times the frames on the same width: drawing per pixel column draws about as much (a few
  // more gap edges), while drawing every sample, as the preview once did, draws ten times more.
  const qsizetype small = paintedBytes(2000);
  const qsizetype large = paintedBytes(20000);
  std::cout << "[ curve paint ] 1600x400, 3 markers + full preview: 2000 frames " << small << " bytes drawn, 20000 frames "
            << large << " bytes\n";
  ASSERT_GT(small, 0);
  EXPECT_LT(large, 2 * small);
}

TEST(SelectionPalette, SelectedMarkersGetDistinctColoursTheFirstThePreference)
{
  EXPECT_EQ(ui::selectionPaletteColor(0), ui::colorScheme().selection);
  for (std::size_t i = 0; i < ui::paletteSize(); ++i)
    for (std::size_t j = i + 1; j < ui::paletteSize(); ++j)
      EXPECT_NE(ui::selectionPaletteColor(i), ui::selectionPaletteColor(j)) << i << " " << j;
  const std::vector<Eigen::Index> selection{3, 7};
  EXPECT_EQ(ui::selectedMarkerColor(selection, 3), ui::selectionPaletteColor(0));
  EXPECT_EQ(ui::selectedMarkerColor(selection, 7), ui::selectionPaletteColor(1));
  EXPECT_FALSE(ui::selectedMarkerColor(selection, 5).isValid());
}

TEST(SmoothingStep, SummaryGivesTheRmsAndLargestChangeInTheDisplayUnit)
{
  Take take = syntheticTake(600, 2);
  // Noise for the smoother to remove: a deterministic zig-zag of ±0.4 mm on x.
  for (Eigen::Index m = 0; m < 2; ++m)
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
      take.setPosition(f, m, take.position(f, m) + Eigen::Vector3d((f % 2 == 0 ? 0.4 : -0.4), 0.0, 0.0));
  ui::SmoothingStep step;
  const ui::StepResult result = step.job()(take, JobControl{});
  ASSERT_FALSE(result.patches.empty());
  double sum = 0.0, largest = 0.0;
  long count = 0;
  for (const SamplePatch& patch : result.patches)
    for (std::size_t i = 0; i < patch.frames.size(); ++i) {
      if (!patch.valid(static_cast<Eigen::Index>(i)) || !take.isValid(patch.frames[i], patch.marker))
        continue;
      const Eigen::Vector3d moved = patch.positions.row(static_cast<Eigen::Index>(i)).transpose();
      const double d = (moved - take.position(patch.frames[i], patch.marker)).norm();
      sum += d * d;
      largest = std::max(largest, d);
      ++count;
    }
  ASSERT_GT(count, 0);
  const double rms = std::sqrt(sum / static_cast<double>(count));
  EXPECT_GT(rms, 0.2) << "the zig-zag is mostly removed";
  const QString summary = result.summary;
  EXPECT_TRUE(summary.contains(QStringLiteral("RMS"))) << summary.toStdString();
  EXPECT_TRUE(summary.contains(QString::number(rms, 'f', 2) + QStringLiteral(" mm"))) << summary.toStdString();
  EXPECT_TRUE(summary.contains(QString::number(largest, 'f', 2) + QStringLiteral(" mm"))) << summary.toStdString();
  step.setDisplayUnit(LengthUnit::Centimetre);
  EXPECT_TRUE(step.job()(take, JobControl{}).summary.contains(QString::number(rms / 10.0, 'f', 3) + QStringLiteral(" cm")));
}

/// The studio on the sample take, for the 3D view's behaviour in the window.
class StudioViews : public ::testing::Test
{
protected:
  void SetUp() override
  {
    QSettings().clear();
    window = std::make_unique<studio::MainWindow>();
    window->resize(1280, 800);
    window->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
    ASSERT_EQ(window->openFile(QString::fromStdString(test::sampleTake().string()), true), QString());
  }

  QAction* actionWithShortcut(const QKeySequence& keys) const
  {
    for (QAction* action : window->findChildren<QAction*>())
      if (action->shortcut() == keys)
        return action;
    return nullptr;
  }

  std::unique_ptr<studio::MainWindow> window;
};

TEST_F(StudioViews, TheThreeDViewDrawsSelectedMarkersInTheirCurveColours)
{
  ui::TakeDocument& doc = window->document();
  ASSERT_EQ(window->selectLabels({QStringLiteral("section3-1"), QStringLiteral("section4-2")}), 2);
  doc.setCurrentFrame(999);
  const auto& selection = doc.selection();
  const auto first = window->markerView()->markerColor(selection[0]);
  const auto second = window->markerView()->markerColor(selection[1]);
  ASSERT_TRUE(first && second);
  EXPECT_NE(*first, *second);
  EXPECT_EQ(*first, ui::selectedMarkerColor(selection, selection[0]));
  EXPECT_EQ(*second, ui::selectedMarkerColor(selection, selection[1]));
}

TEST_F(StudioViews, LayoutHighlightUsesNoSampleStateColourAndEndsWhenThePanelIsLeft)
{
  ui::TakeDocument& doc = window->document();
  doc.setCurrentFrame(1000);
  auto* layoutDock = window->findChild<QDockWidget*>(QStringLiteral("layoutPlanningDock"));
  ASSERT_NE(layoutDock, nullptr);
  layoutDock->raise();
  QApplication::processEvents();
  const Take& take = doc.take();
  std::vector<bool> kept(static_cast<std::size_t>(take.markerCount()), false);
  const Eigen::Index keptMarker = *take.markerIndex("section3-1");
  const Eigen::Index droppedMarker = *take.markerIndex("section4-2");
  kept[static_cast<std::size_t>(keptMarker)] = true;
  window->markerView()->setLayoutHighlight(kept, {});
  ASSERT_EQ(window->markerView()->layoutHighlight().size(), kept.size());
  ui::MarkerView3d* view = window->markerView();
  std::vector<bool> reference(kept.size(), false);
  const Eigen::Index root = *take.markerIndex("root-1");
  reference[static_cast<std::size_t>(root)] = true;
  view->setLayoutHighlight(kept, reference);
  ASSERT_TRUE(view->markerColor(keptMarker) && view->markerColor(droppedMarker) && view->markerColor(root));
  const QColor keptColor = *view->markerColor(keptMarker);
  const QColor droppedColor = *view->markerColor(droppedMarker);
  const QColor referenceColor = *view->markerColor(root);
  for (const QColor& state : {ui::stateColor(SampleOrigin::Measured), ui::stateColor(SampleOrigin::Filled),
                              ui::stateColor(SampleState().with(SampleOperation::Smoothed)), ui::stateColor(SampleOrigin::Edited),
                              ui::colorScheme().flagged, ui::colorScheme().selection}) {
    EXPECT_NE(keptColor, state);
    EXPECT_NE(droppedColor, state);
    EXPECT_NE(referenceColor, state);
  }
  EXPECT_NE(keptColor, droppedColor);
  EXPECT_NE(referenceColor, keptColor);
  EXPECT_NE(referenceColor, droppedColor);
  // Another tab raised over the Layout planning dock: the sample-state colours come back.
  window->findChild<QDockWidget*>(QStringLiteral("cleaningDock"))->raise();
  QApplication::processEvents();
  EXPECT_TRUE(view->layoutHighlight().empty());
  ASSERT_TRUE(view->markerColor(droppedMarker));
  EXPECT_EQ(*view->markerColor(droppedMarker), ui::stateColor(take.state(doc.currentFrame(), droppedMarker)));
}

TEST_F(StudioViews, CtrlBShowsTheStabilizedIndicatorUntilTheLabFrameIsBack)
{
  ui::MarkerView3d* view = window->markerView();
  QAction* stabilize = actionWithShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
  ASSERT_NE(stabilize, nullptr);
  EXPECT_TRUE(view->statusText().isEmpty());
  auto* indicator = view->findChild<QLabel*>(QStringLiteral("viewStatus"));
  // Ctrl+B asks for the reference markers (the head markers are proposed): accept them.
  QTimer accept;
  accept.setInterval(20);
  QObject::connect(&accept, &QTimer::timeout, [&accept] {
    if (auto* dialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget())) {
      dialog->accept();
      accept.stop();
    }
  });
  accept.start();
  stabilize->trigger();
  accept.stop();
  ASSERT_FALSE(view->headReference().empty());
  EXPECT_TRUE(view->statusText().contains(QStringLiteral("Head-stabilized"))) << view->statusText().toStdString();
  ASSERT_NE(indicator, nullptr);
  EXPECT_TRUE(indicator->isVisible());
  EXPECT_EQ(indicator->text(), view->statusText());
  // And on the screen, above the 3D view's native window (a plain child widget would be under
  // it, visible() though never seen): its text colour shows where the label is.
  const QColor text(0xff, 0xd2, 0x7a);
  qsizetype shown = 0;
  QElapsedTimer clock;
  clock.start();
  while ((shown = test::pixelsNear(test::shownOnScreen(*indicator), text, 40)) < 20 && clock.elapsed() < 3000)
    QTest::qWait(20);
  EXPECT_GE(shown, 20) << "the indicator's text is not on the screen";
  stabilize->trigger();  // back to the lab frame
  EXPECT_TRUE(view->headReference().empty());
  EXPECT_TRUE(view->statusText().isEmpty());
  EXPECT_FALSE(indicator->isVisible());
}

TEST_F(StudioViews, FollowHeadKeepsTheCameraOnTheHeadMarkers)
{
  ui::TakeDocument& doc = window->document();
  ui::MarkerView3d* view = window->markerView();
  QAction* follow = actionWithShortcut(QKeySequence(Qt::Key_F));
  ASSERT_NE(follow, nullptr);
  ASSERT_TRUE(follow->isCheckable());
  // The sample's head markers are root-1..6, which the guess finds.
  ASSERT_EQ(view->followedMarkers().size(), 6u);
  follow->setChecked(true);
  EXPECT_TRUE(view->statusText().contains(QStringLiteral("follows")));
  doc.setCurrentFrame(200);
  const Eigen::Vector3d at200 = view->cameraFocalPoint();
  ASSERT_TRUE(view->followTarget(200));
  EXPECT_LT((at200 - *view->followTarget(200)).norm(), 1e-6);
  doc.setCurrentFrame(2500);
  const Eigen::Vector3d at2500 = view->cameraFocalPoint();
  EXPECT_LT((at2500 - *view->followTarget(2500)).norm(), 1e-6);
  EXPECT_GT((at2500 - at200).norm(), 1.0) << "the head moves over the take, and the camera with it";
  // The target is the centroid of the head markers, smoothed: within a few mm of the raw one.
  const Take& take = doc.take();
  Eigen::Vector3d raw = Eigen::Vector3d::Zero();
  for (Eigen::Index m : view->followedMarkers())
    raw += take.position(2500, m);
  raw /= static_cast<double>(view->followedMarkers().size());
  EXPECT_LT((raw - at2500).norm(), 10.0);
  follow->setChecked(false);
  doc.setCurrentFrame(1000);
  EXPECT_LT((view->cameraFocalPoint() - at2500).norm(), 1e-9) << "not following: the camera stays";
}

TEST(CurveView, ARepairedBadPointPreviewsAsADashedLine)
{
  ui::TakeDocument doc;
  Take take = syntheticTake(2000, 2);
  const Eigen::Vector3d truth = take.position(450, 0);
  take.setPosition(450, 0, truth + Eigen::Vector3d(0.0, 0.0, 15.0));  // a spike in z
  doc.setTake(std::move(take));
  doc.setSelection({0});
  ui::CurveView view(doc);
  view.resize(900, 420);
  view.setVisibleRange(440, 460);
  QImage plain(view.size(), QImage::Format_ARGB32_Premultiplied);
  view.render(&plain);
  doc.setPreview(replaceSpikes(doc.take(), {SpikeFlag{0, 450}}));
  ASSERT_EQ(doc.preview().size(), 1u);
  ASSERT_EQ(doc.preview().front().size(), 1u);
  QImage previewed(view.size(), QImage::Format_ARGB32_Premultiplied);
  view.render(&previewed);
  // Pixels changed between the neighbours' columns, away from the repaired sample's dot.
  const auto before = view.pointOf(0, 449, 2), spike = view.pointOf(0, 450, 2), after = view.pointOf(0, 451, 2);
  ASSERT_TRUE(before && spike && after);
  const int left = static_cast<int>(before->x()) + 4, right = static_cast<int>(after->x()) - 4;
  const int dot = static_cast<int>(spike->x());
  int changed = 0;
  for (int x = left; x <= right; ++x) {
    if (std::abs(x - dot) <= 5)
      continue;
    for (int y = 0; y < view.height(); ++y)
      changed += plain.pixel(x, y) != previewed.pixel(x, y) ? 1 : 0;
  }
  EXPECT_GT(changed, 150) << "a dashed line on each side of the repaired sample, on the z strip";
}

} // namespace
} // namespace mocap
