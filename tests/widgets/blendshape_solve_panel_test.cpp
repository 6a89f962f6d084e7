// The Blendshape Solve dock under Xvfb: a small OBJ rig on the sample mesh, solved from the
// sample take off the UI thread; the posed rig in the 3D view, weight curves with click-to-select,
// undoable weight edits, exports, and clear errors.
#include "job_waits.h"
#include "sample_files.h"
#include "../core/test_support.h"

#include "main_window.h"
#include "sample_window.h"

#include "actions/weight_edit_actions.h"
#include "commands/apply_patches_command.h"
#include "document/layout_plan_model.h"
#include "document/studio_session.h"
#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/take_document.h"
#include "panels/blendshape_solve_panel.h"
#include "panels/face_mesh_panel.h"
#include "panels/layout_planning_panel.h"
#include "views/layout_error_plot.h"
#include "views/blendshape_scene.h"
#include "views/face_mesh_scene.h"
#include "views/mesh_layer.h"
#include "views/session_scene.h"
#include "views/weight_curve_view.h"

#include "mocap/base/file_io.h"
#include "mocap/model/sample_patch.h"
#include "checkout_paths.h"

#include <QDockWidget>
#include <QListWidget>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

namespace mocap {
namespace {

using studio::MainWindow;


class BlendshapeSolvePanelTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    test::writeSmallRig(dir);
    window = test::openSampleWindow(1280, 800);
    ASSERT_NE(window, nullptr);
    panel = window->blendshapeSolvePanel();
    ASSERT_NE(panel, nullptr);
  }

  QString neutral() const { return QString::fromStdString(dir.file("neutral.obj").string()); }
  QString shapes() const { return QString::fromStdString(dir.file("shapes").string()); }
  ui::BlendshapeSolveModel& model() const { return panel->model(); }
  ui::TakeDocument& document() const { return window->document(); }

  /// The sample binding on the sample mesh, then the rig (same vertices) and a solve.
  void solveSample()
  {
    ASSERT_EQ(window->loadFaceMesh(test::sampleMesh(), test::sampleBinding()), QString());
    ASSERT_EQ(window->loadRig(neutral(), shapes(), {}, true), QString()) << panel->statusText().toStdString();
  }

  /// The frame where `shape`'s weight peaks.
  Eigen::Index peakFrame(Eigen::Index shape) const
  {
    Eigen::Index frame = 0;
    model().weights().col(shape).maxCoeff(&frame);
    return frame;
  }

  test::TempDir dir;
  std::unique_ptr<MainWindow> window;
  ui::BlendshapeSolvePanel* panel = nullptr;
};

TEST_F(BlendshapeSolvePanelTest, SolvesTheTakeOffTheUiThreadAndPosesTheRigInTheView)
{
  solveSample();
  ASSERT_TRUE(model().hasResult());
  EXPECT_EQ(model().weights().rows(), document().take().frameCount());
  ASSERT_EQ(model().weights().cols(), 3);
  EXPECT_EQ(model().shapeName(0), QStringLiteral("browInnerUp"));  // shapes in name order
  EXPECT_GE(model().weights().minCoeff(), 0.0);
  EXPECT_LE(model().weights().maxCoeff(), 1.0);
  EXPECT_GT(model().weights().maxCoeff(), 0.05) << "the singing face should use the shapes";
  EXPECT_TRUE(panel->statusText().contains(QStringLiteral("Solved"))) << panel->statusText().toStdString();
  EXPECT_TRUE(panel->statusText().contains(QStringLiteral("31 markers"))) << panel->statusText().toStdString();
  EXPECT_EQ(panel->shapeList()->count(), 3);
  EXPECT_TRUE(window->findChild<QDockWidget*>(QStringLiteral("weightsDock"))->isVisible());

  // The posed rig follows the current frame: at a shape's peak it is the neutral plus its delta.
  const Eigen::Index shape = 1;
  const Eigen::Index frame = peakFrame(shape);
  document().setCurrentFrame(frame);
  QApplication::processEvents();
  const ui::MeshLayer& layer = window->sessionScene().blendshapes().layer();
  EXPECT_TRUE(layer.isVisible());
  MeshVertices expected;
  model().rig()->evaluate(model().weights().row(frame).transpose(), expected);
  ASSERT_EQ(layer.vertices().rows(), expected.rows());
  EXPECT_LT((layer.vertices() - expected).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_GT((layer.vertices() - model().rig()->neutral.vertices).cwiseAbs().maxCoeff(), 0.01);
  // Beside the markers (the default) it sits one mesh width and a bit to the side of the face mesh.
  const Eigen::Vector3d shift = layer.placement().translation() -
                                window->faceMeshPanel()->scene().placement()->translation();
  EXPECT_GT(shift.norm(), 1.0);
}

TEST_F(BlendshapeSolvePanelTest, WeightEditsApplyToTheSelectedShapesOverTheRangeAndUndo)
{
  solveSample();
  const Eigen::MatrixXd solved = model().weights();
  model().setSelectedShapes({1});
  document().setRange(100, 400);
  QUndoStack& undo = *document().undoStack();
  const int before = undo.count();
  EXPECT_EQ(panel->edits().scale(0.5), QString());
  EXPECT_EQ(undo.count(), before + 1);
  const Eigen::MatrixXd& scaled = model().weights();
  EXPECT_LT((scaled.col(1).segment(100, 301) - 0.5 * solved.col(1).segment(100, 301)).cwiseAbs().maxCoeff(), 1e-12);
  // Around the range the edit eases in and out: untouched beyond the blend, between the curve
  // and the edit within it, and no step at the range's edges.
  const auto blend = static_cast<Eigen::Index>(
      std::lround(ui::WeightEditActions::kBlendSeconds * document().take().frameRate()));
  ASSERT_GE(blend, 2);
  EXPECT_EQ(scaled.col(1).head(100 - blend), solved.col(1).head(100 - blend));
  EXPECT_EQ(scaled.col(1).tail(scaled.rows() - 401 - blend), solved.col(1).tail(scaled.rows() - 401 - blend));
  const Eigen::VectorXd change = scaled.col(1) - solved.col(1);
  const Eigen::VectorXd full = -0.5 * solved.col(1);  // the change the edit makes inside the range
  for (Eigen::Index f = 100 - blend; f < 100; ++f) {
    EXPECT_LE(std::abs(change(f)), std::abs(full(f)) + 1e-12) << f;
    EXPECT_GE(change(f) * full(f), 0.0) << f;
  }
  const double stepIn = std::abs(change(100) - change(99)), stepOut = std::abs(change(401) - change(400));
  EXPECT_LT(stepIn, 0.5 * std::abs(full(100)) + 1e-9) << "a step into the range";
  EXPECT_LT(stepOut, 0.5 * std::abs(full(400)) + 1e-9) << "a step out of the range";
  EXPECT_EQ(scaled.col(0), solved.col(0));
  EXPECT_EQ(panel->edits().zero(), QString());
  EXPECT_EQ(model().weights().col(1).segment(100, 301).cwiseAbs().maxCoeff(), 0.0);
  undo.undo();
  undo.undo();
  EXPECT_EQ(model().weights(), solved);
  undo.redo();

  // Smoothing keeps the curve inside [0, 1] and makes it smoother within the range.
  undo.undo();
  document().clearRange();
  const auto roughness = [](const Eigen::VectorXd& w) {
    return (w.segment(2, w.size() - 2) - 2.0 * w.segment(1, w.size() - 2) + w.head(w.size() - 2)).squaredNorm();
  };
  model().setSelectedShapes({0, 1, 2});
  EXPECT_EQ(panel->edits().smooth(3.0), QString());
  for (Eigen::Index s = 0; s < 3; ++s) {
    if (roughness(solved.col(s)) > 0.0) {
      EXPECT_LT(roughness(model().weights().col(s)), roughness(solved.col(s))) << s;
    }
  }
  EXPECT_GE(model().weights().minCoeff(), 0.0);
  EXPECT_LE(model().weights().maxCoeff(), 1.0);

  // Editing the take after the solve: the weights stay, and the status says they are stale.
  const Eigen::Index marker = *document().take().markerIndex("section1-1");
  const Eigen::Matrix<double, 1, 3> moved = document().take().position(500, marker).transpose() +
                                            Eigen::RowVector3d(1.0, 0.0, 0.0);
  document().undoStack()->push(new ui::ApplyPatchesCommand(
      document(), {makePatch(marker, {500}, moved, SampleOrigin::Edited)}, QStringLiteral("nudge")));
  EXPECT_TRUE(panel->statusText().contains(QStringLiteral("changed since"))) << panel->statusText().toStdString();
  undo.undo();

  // A new solve replaces the weights: the older edits no longer apply and undo leaves it alone.
  ASSERT_EQ(panel->solve(), QString());
  ASSERT_TRUE(test::waitForJob(panel->jobs()));
  const Eigen::MatrixXd resolved = model().weights();
  undo.undo();
  EXPECT_EQ(model().weights(), resolved);

  // Edits say why they cannot apply.
  model().setSelectedShapes({});
  EXPECT_FALSE(panel->edits().scale(2.0).isEmpty());
  model().setSelectedShapes({0});
  EXPECT_FALSE(panel->edits().smooth(1000.0).isEmpty());
}

TEST_F(BlendshapeSolvePanelTest, ClickingACurveSelectsItsShapeAndTheListFollows)
{
  solveSample();
  ui::WeightCurveView* view = window->weightView();
  ASSERT_NE(view, nullptr);
  view->resize(1000, 300);
  view->show();
  view->repaint();
  // A frame where shape 2 stands apart from the others.
  const Eigen::MatrixXd& w = model().weights();
  Eigen::Index frame = -1;
  double gap = 0.0;
  for (Eigen::Index f = 0; f < w.rows(); ++f) {
    const double apart = std::min(std::abs(w(f, 2) - w(f, 0)), std::abs(w(f, 2) - w(f, 1)));
    if (apart > gap) {
      gap = apart;
      frame = f;
    }
  }
  ASSERT_GT(gap, 0.1);
  const std::optional<QPointF> point = view->pointOf(2, frame);
  ASSERT_TRUE(point.has_value());
  EXPECT_EQ(view->shapeAt(*point), 2);
  EXPECT_TRUE(view->readoutAt(*point).startsWith(QStringLiteral("mouthSmile_L"))) << view->readoutAt(*point).toStdString();
  QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, point->toPoint());
  EXPECT_EQ(model().selectedShapes(), std::vector<Eigen::Index>{2});
  EXPECT_EQ(document().currentFrame(), frame);
  const QList<QListWidgetItem*> selected = panel->shapeList()->selectedItems();
  ASSERT_EQ(selected.size(), 1);
  EXPECT_TRUE(selected.front()->text().startsWith(QStringLiteral("mouthSmile_L")));
  // And selecting in the list selects the shape.
  panel->shapeList()->item(0)->setSelected(true);
  EXPECT_EQ(model().selectedShapes(), (std::vector<Eigen::Index>{0, 2}));
}

TEST_F(BlendshapeSolvePanelTest, ExportsWeightCurvesAndTheAnimatedRig)
{
  solveSample();
  const std::string csv = dir.file("weights.csv").string(), glb = dir.file("rig.glb").string();
  ASSERT_EQ(panel->exportCsv(QString::fromStdString(csv), false), QString());
  const std::string text = readFileBytes(csv);
  EXPECT_EQ(text.substr(0, text.find('\n')), "Frame,Time,browInnerUp,jawOpen,mouthSmile_L");
  EXPECT_EQ(static_cast<Eigen::Index>(std::count(text.begin(), text.end(), '\n')), document().take().frameCount() + 1);
  ASSERT_EQ(panel->exportCsv(QString::fromStdString(dir.file("live.csv").string()), true), QString());
  // Live Link Face's own layout: a real recording's header, the rig's Apple names in their curves.
  const std::string live = readFileBytes(dir.file("live.csv"));
  const std::string recording = readFileBytes(test::dataFile("livelink_face/alex_rom_4_first200.csv"));
  EXPECT_EQ(live.substr(0, live.find('\n')), recording.substr(0, recording.find('\n')));
  EXPECT_EQ(live.substr(live.find('\n') + 1, 19), "00:00:00:00.000,61,");
  ASSERT_EQ(panel->exportGlb(QString::fromStdString(glb)), QString());
  EXPECT_EQ(readFileBytes(glb).substr(0, 4), "glTF");
}

TEST_F(BlendshapeSolvePanelTest, MissingRigBindingOrFolderGiveClearErrors)
{
  EXPECT_TRUE(panel->solve().contains(QStringLiteral("Load a rig")));
  // A shape folder that is not there: an error, and no rig half-loaded.
  QSignalSpy loaded(panel, &ui::BlendshapeSolvePanel::rigLoaded);
  ASSERT_EQ(panel->loadRig(neutral(), QString::fromStdString(dir.file("nowhere").string())), QString());
  ASSERT_TRUE(test::waitForJob(panel->jobs()));
  ASSERT_EQ(loaded.count(), 1);
  EXPECT_FALSE(loaded.front().front().toString().isEmpty());
  EXPECT_FALSE(model().hasRig());
  // A rig without a binding: the neutral becomes the face mesh, and Solve asks for the binding.
  ASSERT_EQ(window->loadRig(neutral(), shapes()), QString());
  EXPECT_TRUE(model().hasRig());
  EXPECT_EQ(window->faceMeshPanel()->model().mesh().vertexCount(), 468);
  EXPECT_TRUE(panel->solve().contains(QStringLiteral("Bind the markers"))) << panel->statusText().toStdString();
  EXPECT_FALSE(model().hasResult());
  EXPECT_FALSE(panel->exportCsv(QString::fromStdString(dir.file("w.csv").string()), false).isEmpty());
  EXPECT_FALSE(std::filesystem::exists(dir.file("w.csv")));
}

TEST_F(BlendshapeSolvePanelTest, LayoutPlanningJudgesLayoutsOnTheLoadedRig)
{
  ui::LayoutPlanningPanel* planning = window->layoutPlanningPanel();
  ui::LayoutPlanParameters quick;
  quick.restarts = 5;
  quick.minK = 3;
  quick.maxK = 10;
  quick.randomSubsets = 3;
  quick.markerPatterns = {QStringLiteral("section*")};
  planning->setParameters(quick);
  planning->setJudgeOnRig(true);
  // No rig yet: Run says what is missing and starts nothing.
  EXPECT_TRUE(planning->run().contains(QStringLiteral("blendshape rig"))) << planning->statusText().toStdString();
  EXPECT_FALSE(planning->busy());

  solveSample();
  ASSERT_EQ(planning->run(), QString()) << planning->statusText().toStdString();
  ASSERT_TRUE(test::waitForJob(planning->jobs()));
  const ui::LayoutPlanResult* result = window->session().layoutPlan().result();
  ASSERT_NE(result, nullptr) << planning->statusText().toStdString();
  ASSERT_TRUE(result->rig.has_value()) << result->rigError.toStdString();
  EXPECT_EQ(result->rig->boundMarkers, 31);
  EXPECT_LT(result->rig->planned.mse, 1e-12);  // every planned marker is the full set
  EXPECT_TRUE(planning->plot()->showsRig());
  planning->plot()->resize(400, 500);
  const auto pfa = planning->plot()->points(ui::LayoutErrorPlot::Measure::RigWeightMse, ui::LayoutErrorPlot::Curve::Pfa);
  EXPECT_GE(pfa.size(), 2u);
  // A reduced layout loses something the full set has.
  const auto& sizes = result->rig->sizes;
  const auto judged = [](const LayoutSizeRigErrors& s) { return s.pfa && s.pfa->judged(); };
  const auto smallest = std::find_if(sizes.begin(), sizes.end(), judged);
  ASSERT_TRUE(smallest != sizes.end());
  EXPECT_GT(smallest->pfa->mse, 1e-6);
  EXPECT_LE(smallest->pfa->boundMarkers, smallest->markerCount);
}

} // namespace
} // namespace mocap
