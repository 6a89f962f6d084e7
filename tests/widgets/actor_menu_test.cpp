// The Actor menu: a profile from the current frame of the sample take that the solve then uses and
// the take remembers, a calibration from a range-of-motion take, and clear errors.
#include "job_waits.h"
#include "sample_files.h"
#include "sample_window.h"
#include "../core/test_support.h"

#include "main_window.h"

#include "actions/actor_actions.h"
#include "document/blendshape_solve_model.h"
#include "document/take_document.h"
#include "panels/blendshape_solve_panel.h"

#include "mocap/deform/actor_profile_io.h"

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>

#include <gtest/gtest.h>

namespace mocap {
namespace {

class ActorMenuTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    test::writeSmallRig(dir);
    window = test::openSampleWindow(1280, 800);
    ASSERT_NE(window, nullptr);
    panel = window->blendshapeSolvePanel();
    ASSERT_EQ(window->loadFaceMesh(test::sampleMesh(), test::sampleBinding()), QString());
    ASSERT_EQ(window->loadRig(test::qpath(dir.file("neutral.obj")), test::qpath(dir.file("shapes"))), QString());
  }
  void TearDown() override { QSettings().clear(); }

  ui::BlendshapeSolveModel& model() const { return panel->model(); }
  ui::ActorActions& actors() const { return panel->actors(); }

  test::TempDir dir;
  std::unique_ptr<studio::MainWindow> window;
  ui::BlendshapeSolvePanel* panel = nullptr;
};

TEST_F(ActorMenuTest, TheMenuBarHasTheActorMenu)
{
  QStringList texts;
  for (QAction* action : window->menuBar()->actions())
    if (action->text() == QStringLiteral("&Actor"))
      for (QAction* item : action->menu()->actions())
        texts << item->text();
  EXPECT_TRUE(texts.contains(QStringLiteral("&New from Neutral Frame…"))) << texts.join(',').toStdString();
  EXPECT_TRUE(texts.contains(QStringLiteral("&Calibrate from ROM Take…")));
  EXPECT_TRUE(texts.contains(QStringLiteral("&Load Actor…")));
}

TEST_F(ActorMenuTest, ANeutralFrameMakesTheActorTheSolveUsesAndTheTakeRemembers)
{
  window->document().setCurrentFrame(40);
  const std::string path = dir.file("alex.json").string();
  ASSERT_EQ(actors().newFromNeutralFrame(QString::fromStdString(path)), QString());
  const ActorProfile profile = readActorProfile(path);
  EXPECT_EQ(profile.name, "alex");
  EXPECT_EQ(profile.labels.size(), profile.binding.markers.size());
  EXPECT_GE(profile.labels.size(), 20U);
  const long long frame = window->document().take().firstFrame() + 40;
  EXPECT_EQ(profile.neutralSource, "Facial-Sing.c3d:" + std::to_string(frame));
  EXPECT_EQ(profile.shapes, model().rig()->shapeNames());
  ASSERT_NE(model().actor(), nullptr);

  // The solve uses it.
  ASSERT_EQ(panel->solve(), QString());
  ASSERT_TRUE(test::waitForJob(panel->jobs()));
  ASSERT_TRUE(model().hasResult()) << panel->statusText().toStdString();
  EXPECT_EQ(model().solvedWith().actor, model().actor());

  // Another take starts without it; the sample take opened again brings it back.
  ASSERT_EQ(window->openFile(test::qpath(test::sampleTake()), true), QString());
  ASSERT_NE(model().actor(), nullptr) << "remembered with the take";
  EXPECT_EQ(model().actorPath(), QString::fromStdString(path));
  actors().clearActor();
  ASSERT_EQ(window->openFile(test::qpath(test::sampleTake()), true), QString());
  EXPECT_EQ(model().actor(), nullptr) << "cleared: forgotten by the take";
}

TEST_F(ActorMenuTest, ARangeOfMotionTakeCalibratesTheLoadedActor)
{
  EXPECT_FALSE(actors().calibrateFromRom(test::qpath(test::sampleTake()), test::qpath(dir.file("c.json"))).isEmpty())
      << "no actor loaded yet";
  ASSERT_EQ(actors().newFromNeutralFrame(test::qpath(dir.file("alex.json"))), QString());
  ASSERT_EQ(actors().calibrateFromRom(test::qpath(test::sampleTake()), test::qpath(dir.file("calibrated.json"))),
            QString());
  const ActorProfile calibrated = readActorProfile(dir.file("calibrated.json"));
  EXPECT_EQ(calibrated.romSource, "Facial-Sing.c3d");
  ASSERT_EQ(calibrated.romMaximum.size(), 3);
  EXPECT_TRUE(calibrated.romMaximum.allFinite());
  EXPECT_EQ(model().actorPath(), test::qpath(dir.file("calibrated.json")));
  EXPECT_TRUE(std::filesystem::exists(dir.file("alex.json"))) << "the uncalibrated profile is kept";
}

TEST_F(ActorMenuTest, BadProfilesAreClearErrorsAndChangeNothing)
{
  EXPECT_FALSE(actors().loadActor(test::qpath(dir.file("missing.json"))).isEmpty());
  EXPECT_EQ(model().actor(), nullptr);
  window->document().setCurrentFrame(0);
  ASSERT_EQ(actors().newFromNeutralFrame(test::qpath(dir.file("alex.json"))), QString());
  ActorProfile other = readActorProfile(dir.file("alex.json"));
  other.shapes = {"a", "b", "c"};  // made for another rig
  writeActorProfile(dir.file("other.json"), other);
  actors().clearActor();
  EXPECT_FALSE(actors().loadActor(test::qpath(dir.file("other.json"))).isEmpty());
  EXPECT_EQ(model().actor(), nullptr);
}

} // namespace
} // namespace mocap
