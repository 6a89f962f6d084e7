// The Face mesh dock under Xvfb: the sample mesh and binding driven by the sample take, binding
// edits by picking (undoable), RBF vs Laplacian, clear errors, and a render against a baseline.
#include "job_waits.h"
#include "sample_files.h"
#include "../core/test_support.h"

#include "commands/apply_patches_command.h"
#include "image_difference.h"

#include "dialogs/export_dialog.h"
#include "document/take_document.h"
#include "main_window.h"
#include "sample_window.h"
#include "panels/face_mesh_panel.h"
#include "document/face_mesh_model.h"
#include "views/face_mesh_scene.h"
#include "views/session_scene.h"
#include "views/marker_view_3d.h"
#include "views/mesh_layer.h"
#include "views/vtk_viewport.h"

#include "mocap/deform/face_rig.h"
#include "mocap/base/file_io.h"
#include "mocap/io/pc2_io.h"
#include "checkout_paths.h"

#include <QAction>
#include <QComboBox>
#include <QSettings>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace mocap {
namespace {

using studio::MainWindow;
using ui::FaceMeshModel;
using ui::FaceMeshScene;

constexpr Eigen::Index kStart = 1000;  // the actor sings here: the mouth markers move

class FaceMeshPanelTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    window = test::openSampleWindow(1280, 800);
    ASSERT_NE(window, nullptr);
    ASSERT_EQ(window->loadFaceMesh(test::sampleMesh(), test::sampleBinding()), QString());
    panel = window->faceMeshPanel();
  }

  /// The face mesh as the 3D view draws it (the window's session scene; the panel observes it).
  [[nodiscard]] FaceMeshScene& scene() const { return window->sessionScene().faceMesh(); }
  [[nodiscard]] FaceMeshModel& model() const { return panel->model(); }
  [[nodiscard]] ui::TakeDocument& document() const { return window->document(); }

  /// Steps the document through frames kStart … kStart + 10, as playback does, and returns the
  /// mesh drawn at the first and the last.
  std::pair<MeshVertices, MeshVertices> playTenFrames() const
  {
    document().setCurrentFrame(kStart);
    const MeshVertices first = scene().layer().vertices();
    for (Eigen::Index f = kStart + 1; f <= kStart + 10; ++f) {
      document().setCurrentFrame(f);
      QApplication::processEvents();
    }
    return {first, scene().layer().vertices()};
  }

  std::unique_ptr<MainWindow> window;
  ui::FaceMeshPanel* panel = nullptr;
};

TEST_F(FaceMeshPanelTest, PlayingMovesBoundVerticesWithTheirMarkersAndFarVerticesLittle)
{
  const FaceRig* rig = model().rig();
  ASSERT_NE(rig, nullptr) << model().error().toStdString();
  ASSERT_EQ(rig->markers().size(), 31u);
  const auto [before, after] = playTenFrames();
  ASSERT_EQ(after.rows(), 468);
  const Take& take = model().rigTake();
  double largest = 0.0, error = 0.0, motion = 0.0;
  std::vector<double> controlMotion;
  for (std::size_t k = 0; k < rig->markers().size(); ++k) {
    const Eigen::Index m = rig->markers()[k];
    const MeshPoint& point = rig->points()[k];
    ASSERT_TRUE(take.isValid(kStart, m) && take.isValid(kStart + 10, m)) << take.label(m);
    const Eigen::Vector3d expected = rig->retarget().map(take.position(kStart + 10, m) - take.position(kStart, m));
    const Eigen::Vector3d moved = point.on(after) - point.on(before);
    // RBF interpolates its controls, but a point bound inside a triangle moves with the triangle's
    // corners: each bound point moves about as its retargeted marker (cm on the mesh).
    EXPECT_LT((moved - expected).norm(), 0.25 * expected.norm() + 0.005) << take.label(m) << " " << expected.norm();
    error += (moved - expected).norm();
    motion += expected.norm();
    largest = std::max(largest, expected.norm());
    controlMotion.push_back(expected.norm());
    // And it is drawn where the view draws the marker (up to the binding's residual).
    const Eigen::Vector3d drawn = scene().layer().placement() * point.on(after);
    EXPECT_LT((drawn - window->markerView()->displayPosition(kStart + 10, m)).norm(), 12.0) << take.label(m);
  }
  ASSERT_GT(largest, 0.2) << "the markers should move over these frames (cm on the mesh)";
  EXPECT_LT(error, 0.1 * motion);
  // Vertices whose nearest control hardly moved move far less than the controls that moved most.
  const PointSet controls = boundPositions(rig->rest(), rig->points());
  double farMotion = 0.0;
  int farCount = 0;
  for (Eigen::Index v = 0; v < after.rows(); ++v) {
    Eigen::Index nearest = 0;
    (controls.rowwise() - rig->rest().row(v)).rowwise().squaredNorm().minCoeff(&nearest);
    if (controlMotion[static_cast<std::size_t>(nearest)] < 0.1 * largest) {
      farMotion = std::max(farMotion, (after.row(v) - before.row(v)).norm());
      ++farCount;
    }
  }
  EXPECT_GT(farCount, 20);
  EXPECT_LT(farMotion, 0.5 * largest);
  EXPECT_GE(scene().lastDeformMs(), 0.0);
  EXPECT_TRUE(panel->timingText().contains(QStringLiteral("RBF")));
}

TEST_F(FaceMeshPanelTest, LaplacianFollowsTheMarkersAndCompareDrawsBothMethods)
{
  auto* method = panel->findChild<QComboBox*>(QStringLiteral("method"));
  ASSERT_NE(method, nullptr);
  method->setCurrentIndex(1);
  ASSERT_NE(model().rig(), nullptr) << model().error().toStdString();
  EXPECT_EQ(model().rig()->options().method, DeformMethod::Laplacian);
  EXPECT_EQ(QSettings().value(QStringLiteral("faceMesh/method")).toInt(), static_cast<int>(DeformMethod::Laplacian));
  const auto [before, after] = playTenFrames();
  const FaceRig& rig = *model().rig();
  const Take& take = model().rigTake();
  double error = 0.0, motion = 0.0;
  for (std::size_t k = 0; k < rig.markers().size(); ++k) {
    const Eigen::Index m = rig.markers()[k];
    const Eigen::Vector3d expected = rig.retarget().map(take.position(kStart + 10, m) - take.position(kStart, m));
    error += (rig.points()[k].on(after) - rig.points()[k].on(before) - expected).norm();
    motion += expected.norm();
  }
  // Soft constraints: the bound points follow most of the way.
  EXPECT_LT(error, 0.5 * motion);

  model().setCompare(true);
  ASSERT_NE(model().compareRig(), nullptr);
  EXPECT_EQ(model().compareRig()->options().method, DeformMethod::Rbf);
  document().setCurrentFrame(kStart + 20);
  EXPECT_TRUE(scene().compareLayer().isVisible());
  EXPECT_GE(scene().lastCompareMs(), 0.0);
  const QString timing = panel->timingText();
  EXPECT_TRUE(timing.contains(QStringLiteral("Laplacian")) && timing.contains(QStringLiteral("RBF")))
      << timing.toStdString();
  // Beside the first mesh, not on it.
  EXPECT_GT((scene().compareLayer().scenePosition(0) - scene().layer().scenePosition(0)).norm(), 50.0);
  std::cout << "[ measured ] " << timing.toStdString() << '\n';
}

TEST_F(FaceMeshPanelTest, PickingAVertexRebindsTheSelectedMarkerUndoably)
{
  ui::VtkViewport* viewport = window->markerView()->viewport();
  ASSERT_TRUE(viewport->usable()) << viewport->failureReason().toStdString();
  document().setCurrentFrame(kStart);
  QTest::qWait(200);  // a render, so the camera is set up
  const Eigen::Index marker = *document().take().markerIndex("section7-1");
  const MeshBinding original = model().binding();
  const auto bindingOf = [this](const std::string& label) {
    for (const MarkerBinding& b : model().binding().markers)
      if (b.label == label)
        return b.point;
    return MeshPoint{};
  };
  const MeshPoint was = bindingOf("section7-1");
  // A vertex that picks back to itself and lies clear of every drawn marker.
  Eigen::Index target = -1;
  QPoint where;
  for (Eigen::Index v = 0; v < 468 && target < 0; v += 7) {
    const QPoint p = viewport->widgetPosition(scene().layer().scenePosition(v)).toPoint();
    if (!viewport->rect().contains(p) || window->markerView()->markerAt(p, 15) >= 0 ||
        scene().layer().vertexAt(viewport->displayPixel(p)) != v || was.vertices[0] == v)
      continue;
    target = v;
    where = p;
  }
  ASSERT_GE(target, 0);

  panel->setPicking(true);
  document().setSelection({marker});
  EXPECT_EQ(panel->pendingLabel(), "section7-1");
  QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, where);
  const MeshPoint now = bindingOf("section7-1");
  EXPECT_TRUE(now.isVertex());
  EXPECT_EQ(now.vertices[0], target);
  EXPECT_EQ(document().selection(), std::vector<Eigen::Index>{marker});  // the click did not deselect it
  EXPECT_EQ(model().binding().markers.size(), original.markers.size());
  EXPECT_EQ(panel->undoStack()->count(), 1);
  ASSERT_NE(model().rig(), nullptr);  // set up again with the new binding
  // The pick says where and how well: the vertex, and the marker's new residual beside the old.
  const QString status = panel->statusText();
  EXPECT_TRUE(status.contains(QStringLiteral("vertex %1").arg(target))) << status.toStdString();
  EXPECT_TRUE(status.contains(QStringLiteral("residual")) && status.contains(QStringLiteral("mm (was")))
      << status.toStdString();
  EXPECT_TRUE(std::isfinite(panel->pickResidual(marker)));
  panel->undoStack()->undo();
  EXPECT_EQ(bindingOf("section7-1").vertices, was.vertices);
  // Without picking, the same click only changes the view's selection.
  panel->setPicking(false);
  document().setSelection({marker});
  QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, where);
  EXPECT_EQ(bindingOf("section7-1").vertices, was.vertices);
  EXPECT_EQ(panel->undoStack()->index(), 0);
  panel->undoStack()->redo();
  EXPECT_EQ(bindingOf("section7-1").vertices[0], target);
  // One undo history: the binding edit and a take edit undo in order, with Ctrl+Z's stack.
  ASSERT_EQ(panel->undoStack(), document().undoStack());
  document().undoStack()->push(new ui::ApplyPatchesCommand(
      document(), {deleteSamples(document().take(), marker, 10, 12)}, QStringLiteral("delete")));
  document().undoStack()->undo();  // the take edit first
  EXPECT_TRUE(document().take().isValid(11, marker));
  EXPECT_EQ(bindingOf("section7-1").vertices[0], target);
  document().undoStack()->undo();  // then the binding edit
  EXPECT_EQ(bindingOf("section7-1").vertices, was.vertices);
  document().undoStack()->redo();
  EXPECT_EQ(bindingOf("section7-1").vertices[0], target);
  // Saved and read back, the edited binding is the same (and starts a new history).
  test::TempDir dir;
  const QString saved = QString::fromStdString(dir.file("edited.binding.json").string());
  ASSERT_EQ(panel->saveBinding(saved), QString());
  ASSERT_EQ(panel->loadBinding(saved), QString());
  EXPECT_EQ(bindingOf("section7-1").vertices[0], target);
  EXPECT_EQ(model().binding().markers.size(), original.markers.size());
  // The edit was for the binding now replaced: undoing it changes nothing and drops it.
  const int before = document().undoStack()->count();
  document().undoStack()->undo();  // the binding edit (the take edit after it was undone above)
  EXPECT_EQ(bindingOf("section7-1").vertices[0], target);
  EXPECT_LT(document().undoStack()->count(), before);
}

TEST_F(FaceMeshPanelTest, TheMeshStaysOnTheMarkersInTheHeadStabilizedView)
{
  ui::MarkerView3d* view = window->markerView();
  std::vector<Eigen::Index> reference;
  for (const char* label : {"root-1", "root-2", "root-3", "root-4", "root-5", "root-6"})
    reference.push_back(*document().take().markerIndex(label));
  ASSERT_EQ(view->setHeadReference(reference), QString());
  document().setCurrentFrame(kStart + 500);
  const FaceRig& rig = *model().rig();
  const Eigen::Index frame = kStart + 500;
  double worst = 0.0;
  for (std::size_t k = 0; k < rig.markers().size(); ++k) {
    const Eigen::Index m = rig.markers()[k];
    if (!document().take().isValid(frame, m))
      continue;
    const Eigen::Vector3d drawn = scene().layer().placement() * rig.points()[k].on(scene().layer().vertices());
    worst = std::max(worst, (drawn - view->displayPosition(frame, m)).norm());
  }
  EXPECT_LT(worst, 12.0);  // mm: the binding's residuals, not the head's motion
  const Eigen::Index first = rig.markers()[0];
  ASSERT_GT((view->displayPosition(frame, first) - document().take().position(frame, first)).norm(), 2.0 * worst)
      << "the head should have moved, or this checks nothing";
  // The stabilized frame differs from the lab frame by the head pose, so the placement changed.
  ASSERT_EQ(view->setHeadReference({}), QString());
  document().setCurrentFrame(frame + 1);
  document().setCurrentFrame(frame);
  const Eigen::Vector3d lab = scene().layer().placement() * rig.points()[0].on(scene().layer().vertices());
  EXPECT_LT((lab - view->displayPosition(frame, rig.markers()[0])).norm(), 12.0);
}

TEST_F(FaceMeshPanelTest, BadFilesGiveClearErrorsAndKeepTheMesh)
{
  test::TempDir dir;
  const std::string notAMesh = dir.file("broken.obj").string();
  writeFileAtomically(notAMesh, "v 1 2\nf 1 2 3\n");
  EXPECT_FALSE(panel->loadMesh(QString::fromStdString(notAMesh)).isEmpty());
  EXPECT_EQ(model().mesh().vertexCount(), 468);  // the loaded mesh stays
  const std::string stranger = dir.file("stranger.json").string();
  writeFileAtomically(stranger, R"({"markers": {"chin_tip": 1, "section1-1": 5, "section2-1": 9}})");
  const QString error = panel->loadBinding(QString::fromStdString(stranger));
  EXPECT_TRUE(error.contains(QStringLiteral("chin_tip"))) << error.toStdString();
  EXPECT_EQ(model().rig(), nullptr);
  document().setCurrentFrame(kStart + 3);  // no rig: nothing deforms and nothing crashes
  EXPECT_LT(scene().lastDeformMs(), 0.0);
  const std::string offMesh = dir.file("off.json").string();
  writeFileAtomically(offMesh, R"({"markers": {"section1-1": 468}})");
  EXPECT_TRUE(panel->loadBinding(QString::fromStdString(offMesh)).contains(QStringLiteral("bound off the mesh")));
  // Auto-bind gets the face back: every face marker, the head references left out.
  EXPECT_EQ(panel->autoBind(), QString());
  ASSERT_NE(model().rig(), nullptr);
  EXPECT_EQ(model().binding().markers.size(), 31u);
}

TEST_F(FaceMeshPanelTest, RendersTheMeshOverTheMarkersLikeTheBaseline)
{
  ui::VtkViewport* viewport = window->markerView()->viewport();
  ASSERT_TRUE(viewport->usable()) << viewport->failureReason().toStdString();
  document().setCurrentFrame(999);
  viewport->setFixedSize(480, 360);
  window->markerView()->resetCamera();
  QTest::qWait(200);
  const QImage image = viewport->grabFramebuffer();
  ASSERT_FALSE(image.isNull());
  // The mesh covers the face: far more light-grey pixels than the markers alone give.
  int grey = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      grey += c.saturation() < 40 && c.value() > 110 ? 1 : 0;
    }
  EXPECT_GT(grey, image.width() * image.height() / 20);
  EXPECT_TRUE(test::matchesBaseline(image, QStringLiteral("FaceMeshView")));
  // The comparison misses no marker, not even one drawn white on the light-grey mesh: hiding any
  // one changes its disc, and nothing else, by more than the comparison allows.
  const ui::MarkerView3d* view = window->markerView();
  int hidden = 0;
  qsizetype fewest = image.width() * image.height();
  for (Eigen::Index m = 0; m < document().take().markerCount(); ++m) {
    const auto centre = view->screenPosition(m);
    if (!centre)
      continue;
    document().setHidden({m}, true);
    const test::ImageDifference difference = test::compareImages(viewport->grabFramebuffer(), image);
    document().setHidden({m}, false);
    const std::string label = document().take().label(m);
    EXPECT_FALSE(difference.matches()) << label << ": only " << difference.differing << " pixels differ";
    EXPECT_TRUE(QRectF(*centre - QPointF(12.0, 12.0), QSizeF(24.0, 24.0)).contains(QRectF(difference.bounds))) << label;
    fewest = std::min(fewest, difference.differing);
    ++hidden;
  }
  EXPECT_GE(hidden, 30);
  std::cout << "[ measured ] hiding one of " << hidden << " markers over the mesh changes at least " << fewest
            << " pixels\n";
  EXPECT_TRUE(test::compareImages(viewport->grabFramebuffer(), image).matches()) << "shown again, as it was";
}

TEST_F(FaceMeshPanelTest, ExportAnimationWritesTheDeformedMeshOfTheLoadedFace)
{
  QAction* action = nullptr;
  for (QAction* candidate : window->findChildren<QAction*>())
    if (candidate->text() == QStringLiteral("Export Ani&mation…"))
      action = candidate;
  ASSERT_NE(action, nullptr);
  test::TempDir dir;
  const std::filesystem::path cache = dir.file("face.pc2");
  const Eigen::Index first = document().take().firstFrame() + kStart;
  bool exported = false;
  QTimer::singleShot(0, [&] {  // inside the dialog's exec()
    auto* dialog = qobject_cast<ui::ExportDialog*>(QApplication::activeModalWidget());
    if (!dialog)
      return;
    dialog->setFormat(ui::AnimationFormat::ObjPlusPc2);
    dialog->setOutputPath(QString::fromStdString(cache.string()));
    dialog->setFrameRange(first, first + 9);
    exported = dialog->format() == ui::AnimationFormat::ObjPlusPc2 && dialog->startExport();
    EXPECT_TRUE(test::waitForJob(dialog->jobs()));
    dialog->close();
  });
  action->trigger();
  ASSERT_TRUE(exported) << "the mesh formats are offered once a face mesh is loaded";
  const PointCache written = readPc2(cache);
  ASSERT_EQ(written.samples.size(), 10u);
  // The same rig, set up independently, gives the cached vertices (float precision).
  FaceRig rig(model().mesh(), model().binding(), model().rigTake(), model().options());
  MeshVertices expected;
  (void)rig.deform(model().rigTake(), kStart + 5, expected);
  EXPECT_LT((written.samples[5].cast<double>() - expected).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_GT((written.samples[9] - written.samples[0]).cwiseAbs().maxCoeff(), 0.01f) << "the face moves";
}

} // namespace
} // namespace mocap
