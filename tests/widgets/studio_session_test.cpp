// The studio session under Xvfb (issue 31): context belongs to one take. After the sample with
// its face mesh, a body take from another lab opens without the face (no mesh drawn, no markers
// claimed bound, the camera framed on the body); a rig kept on request is re-bound to the labels
// each take has, and the docks say how many of its markers were found.
#include "sample_files.h"
#include "../core/test_support.h"
#include "foreign_takes.h"

#include "main_window.h"
#include "sample_window.h"

#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "panels/face_mesh_panel.h"
#include "views/face_mesh_scene.h"
#include "views/marker_view_3d.h"
#include "views/mesh_layer.h"
#include "views/vtk_viewport.h"

#include "mocap/io/take_io.h"
#include "mocap/model/marker_edits.h"
#include "checkout_paths.h"

#include <QAction>
#include <QSettings>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <gtest/gtest.h>

#include <algorithm>

namespace mocap {
namespace {

using test::qpath;


class StudioSessionTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    window = test::openSampleWindow(1280, 800);
    ASSERT_NE(window, nullptr);
    ASSERT_EQ(window->loadFaceMesh(test::sampleMesh(), test::sampleBinding()), QString());
    ASSERT_NE(faceMesh().rig(), nullptr);
    bound = faceMesh().binding().markers.size();
    ASSERT_GT(bound, 10u);
  }

  [[nodiscard]] ui::FaceMeshModel& faceMesh() const { return window->session().faceMesh(); }
  [[nodiscard]] ui::FaceMeshPanel& panel() const { return *window->faceMeshPanel(); }

  /// A body take from another lab (a Nexus pelvis: none of the face's labels), as a C3D file.
  QString writeBodyTake() const
  {
    const std::filesystem::path path = dir.file("body.c3d");
    writeTake(test::nexusCleaningTake(), path.string());
    return qpath(path);
  }

  /// The sample take without its first `dropped` bound markers, as a C3D file.
  QString writeSampleWithout(std::size_t dropped) const
  {
    const Take sample = readTake(test::sampleTake().string());
    std::vector<std::string> kept;
    for (Eigen::Index m = 0; m < sample.markerCount(); ++m)
      kept.push_back(sample.label(m));
    for (std::size_t i = 0; i < dropped; ++i)
      kept.erase(std::remove(kept.begin(), kept.end(), faceMesh().binding().markers[i].label), kept.end());
    const std::filesystem::path path = dir.file("fewer.c3d");
    writeTake(subsetTake(sample, kept), path.string());
    return qpath(path);
  }

  void keepRig(bool on) const
  {
    auto* action = window->findChild<QAction*>(QStringLiteral("keepRigAction"));
    ASSERT_NE(action, nullptr);
    action->setChecked(on);
  }

  test::TempDir dir;
  std::unique_ptr<studio::MainWindow> window;
  std::size_t bound = 0;
};

TEST_F(StudioSessionTest, AnotherTakeStartsWithoutThePreviousTakesFaceMeshAndFramesItsOwnMarkers)
{
  ASSERT_EQ(window->openFile(writeBodyTake(), true), QString());
  EXPECT_FALSE(faceMesh().hasMesh());
  EXPECT_TRUE(faceMesh().binding().markers.empty());
  EXPECT_EQ(faceMesh().rig(), nullptr);
  EXPECT_FALSE(window->session().blendshapes().hasRig());
  // The dock claims no marker of the sample bound.
  EXPECT_FALSE(panel().bindingSummary().contains(QString::number(bound))) << panel().bindingSummary().toStdString();
  EXPECT_FALSE(panel().scene().layer().isVisible());

  // Reset Camera frames the body's markers, not a head left from the sample.
  const Take& take = window->document().take();
  Eigen::AlignedBox3d markers;
  for (Eigen::Index m = 0; m < 4; ++m)  // LASI, RASI, LPSI, RPSI: the markers (the rest are model outputs)
    markers.extend(take.position(0, m));
  window->markerView()->resetCamera();
  Eigen::Vector3d focal;
  window->markerView()->viewport()->renderer()->GetActiveCamera()->GetFocalPoint(focal.data());
  EXPECT_LT((focal - markers.center()).norm(), markers.diagonal().norm())
      << "focal point " << focal.transpose() << ", markers' centre " << markers.center().transpose();
}

TEST_F(StudioSessionTest, AKeptRigIsReboundToTheMarkersEachTakeHasAndSaysHowManyWereFound)
{
  keepRig(true);
  EXPECT_TRUE(QSettings().value(QStringLiteral("session/keepRig")).toBool());  // remembered
  const QString total = QString::number(bound);

  ASSERT_EQ(window->openFile(writeSampleWithout(3), true), QString());
  ASSERT_TRUE(faceMesh().hasMesh());
  EXPECT_EQ(faceMesh().binding().markers.size(), bound - 3);
  EXPECT_EQ(faceMesh().keptRigMarkers(), bound);
  EXPECT_NE(faceMesh().rig(), nullptr) << faceMesh().error().toStdString();  // set up on the markers found
  EXPECT_TRUE(panel().bindingSummary().startsWith(
      QStringLiteral("%1 of %2 rig marker(s) found in this take").arg(bound - 3).arg(total)))
      << panel().bindingSummary().toStdString();

  // A take with none of them: nothing bound, nothing drawn, and the rig is still the actor's.
  ASSERT_EQ(window->openFile(writeBodyTake(), true), QString());
  EXPECT_TRUE(faceMesh().binding().markers.empty());
  EXPECT_EQ(faceMesh().rig(), nullptr);
  EXPECT_FALSE(panel().scene().layer().isVisible());
  EXPECT_TRUE(panel().bindingSummary().startsWith(QStringLiteral("0 of %1 rig marker(s)").arg(total)))
      << panel().bindingSummary().toStdString();

  // Back on the sample every marker of the rig is found again.
  ASSERT_EQ(window->openFile(qpath(test::sampleTake()), true), QString());
  EXPECT_EQ(faceMesh().binding().markers.size(), bound);
  EXPECT_NE(faceMesh().rig(), nullptr) << faceMesh().error().toStdString();

  // Off again: the next take starts without the rig.
  keepRig(false);
  ASSERT_EQ(window->openFile(writeBodyTake(), true), QString());
  EXPECT_FALSE(faceMesh().hasMesh());
}

} // namespace
} // namespace mocap
