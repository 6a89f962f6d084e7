// The session's models without a window (issue 31): the take's reference videos with their
// sidecar, and the layout plan with its highlight, owned by a StudioSession alone (no MainWindow,
// no dock): what the Reference Video and Layout planning docks only show.
#include "../core/coded_video.h"
#include "../core/test_support.h"
#include "sample_files.h"

#include "commands/remove_markers_command.h"
#include "document/face_mesh_model.h"
#include "document/layout_plan_model.h"
#include "document/reference_video.h"
#include "document/reference_videos.h"
#include "document/studio_session.h"
#include "document/session_files.h"
#include "document/take_document.h"

#include "mocap/io/take_io.h"
#include "mocap/video/reference_video_sidecar.h"

#include <opencv2/videoio.hpp>

#include <QSignalSpy>
#include <QUndoStack>

#include <gtest/gtest.h>

namespace mocap {
namespace {

QString sessionModelsPath(const std::filesystem::path& path)
{
  return QString::fromStdString(path.string());
}

/// A three-frame take with these markers, written to `path` and opened in `session`.
void openSmallTake(ui::StudioSession& session, const std::filesystem::path& path, std::vector<std::string> labels)
{
  writeTake(Take(std::move(labels), 3, 100.0), path.string());
  session.document().open(ui::TakeDocument::read(sessionModelsPath(path)), sessionModelsPath(path));
}

TEST(SessionReferenceVideos, AreTheTakesOwnRememberedBesideItAndRestoredByANewSession)
{
  test::TempDir dir;
  ASSERT_TRUE(test::writeCodedVideo(dir.file("hmc.avi"), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0, 50, 96, 64));
  const auto take = dir.file("take.c3d");
  {
    ui::StudioSession session;
    openSmallTake(session, take, {"a", "b"});
    ui::ReferenceVideos& videos = session.referenceVideos();
    QSignalSpy inserted(&videos, &ui::ReferenceVideos::videoInserted);
    ASSERT_EQ(videos.open(sessionModelsPath(dir.file("hmc.avi"))), QString());
    EXPECT_EQ(inserted.count(), 1);
    ASSERT_EQ(videos.count(), 1);
    ASSERT_NE(videos.current(), nullptr);
    EXPECT_TRUE(videos.current()->isActive()) << "the current video decodes";
    videos.current()->setOffset(0.25);
    EXPECT_FALSE(videos.open(sessionModelsPath(dir.file("none.avi"))).isEmpty());
    EXPECT_EQ(videos.count(), 1) << "a video that cannot be shown is not linked";
    videos.save();
    ASSERT_TRUE(std::filesystem::exists(referenceVideoSidecarPath(take)));

    // Another take in the same session starts without the first take's videos.
    QSignalSpy removed(&videos, &ui::ReferenceVideos::videoAboutToBeRemoved);
    openSmallTake(session, dir.file("other.c3d"), {"c"});
    EXPECT_EQ(removed.count(), 1);
    EXPECT_EQ(videos.count(), 0);
    EXPECT_EQ(videos.current(), nullptr);
  }
  // A new session opening the take restores the video with its offset, and says so.
  ui::StudioSession session;
  QSignalSpy restored(&session.referenceVideos(), &ui::ReferenceVideos::restored);
  openSmallTake(session, dir.file("unused.c3d"), {"x"});
  session.document().open(ui::TakeDocument::read(sessionModelsPath(take)), sessionModelsPath(take));
  const ui::ReferenceVideos& videos = session.referenceVideos();
  ASSERT_EQ(videos.count(), 1);
  EXPECT_FALSE(videos.isMissing(0));
  EXPECT_DOUBLE_EQ(videos.at(0).offset(), 0.25);
  ASSERT_FALSE(restored.isEmpty());
  EXPECT_EQ(restored.back().at(0).toInt(), 1);
  EXPECT_EQ(restored.back().at(1).toInt(), 0);
}

/// A plan over markers a, b, c (head markers h1, h2) with one two-marker layout: a and c.
std::shared_ptr<ui::LayoutPlanResult> twoMarkerPlan()
{
  auto result = std::make_shared<ui::LayoutPlanResult>();
  result->frames.labels = {"a", "b", "c"};
  result->stabilizeLabels = {"h1", "h2"};
  LayoutSize size;
  size.markerCount = 2;
  size.pfa = ScoredLayout{};
  size.pfa->markers = {0, 2};
  result->plan.sizes.push_back(size);
  return result;
}

TEST(SessionLayoutPlan, HighlightsThePickedLayoutOnTheOpenTakeByLabel)
{
  test::TempDir dir;
  ui::StudioSession session;
  // The open take orders its markers differently and lacks h2.
  openSmallTake(session, dir.file("take.c3d"), {"c", "h1", "b", "a", "z"});
  ui::LayoutPlanModel& plan = session.layoutPlan();
  EXPECT_TRUE(plan.highlight().kept.empty()) << "no plan, nothing to highlight";
  QSignalSpy changed(&plan, &ui::LayoutPlanModel::changed);
  plan.setResult(twoMarkerPlan(), 2);
  EXPECT_EQ(changed.count(), 1);
  EXPECT_EQ(plan.selectedLabels(), (std::vector<std::string>{"a", "c"}));
  EXPECT_EQ(plan.captureLabels(), (std::vector<std::string>{"a", "c", "h1", "h2"}));
  const ui::LayoutHighlight shown = plan.highlight();
  EXPECT_EQ(shown.kept, (std::vector<bool>{true, false, false, true, false}));
  EXPECT_EQ(shown.reference, (std::vector<bool>{false, true, false, false, false}));
  // A size the plan has no layout for shows nothing.
  plan.setSelectedSize(3);
  EXPECT_TRUE(plan.highlight().kept.empty());
  EXPECT_TRUE(plan.selectedLabels().empty());
  // Removing a marker (b) maps the highlight again.
  plan.setSelectedSize(2);
  QSignalSpy remap(&plan, &ui::LayoutPlanModel::highlightChanged);
  session.undoStack()->push(new ui::RemoveMarkersCommand(session.document(), {2}));
  EXPECT_GE(remap.count(), 1);
  EXPECT_EQ(plan.highlight().kept, (std::vector<bool>{true, false, true, false}));
}

TEST(SessionRecovery, RestoresTheFaceMeshAndItsBindingStraightFromTheState)
{
  ui::SessionFiles files;
  files.take = QString::fromStdString(test::sampleTake().string());
  files.mesh = test::sampleMesh();
  files.binding = test::sampleBinding();
  ui::StudioSession crashed;
  ASSERT_EQ(ui::loadSessionFiles(crashed, files), QString());
  const ui::FaceMeshModel& before = crashed.faceMesh();
  ASSERT_NE(before.rig(), nullptr);
  const QVariantMap state = crashed.recoveryState();

  ui::StudioSession recovered;
  recovered.document().setTake(crashed.document().take());
  EXPECT_TRUE(recovered.recoveryState().isEmpty()) << "no face mesh, nothing to keep";
  ASSERT_EQ(recovered.restoreRecoveryState(state), QString());
  const ui::FaceMeshModel& after = recovered.faceMesh();
  EXPECT_EQ(after.meshPath(), before.meshPath());
  ASSERT_EQ(after.binding().markers.size(), before.binding().markers.size());
  EXPECT_EQ(after.binding().markers.front().label, before.binding().markers.front().label);
  EXPECT_NE(after.rig(), nullptr);
  QVariantMap broken = state;
  broken.insert(QStringLiteral("binding"), QStringLiteral("{"));
  EXPECT_FALSE(recovered.restoreRecoveryState(broken).isEmpty()) << "a damaged binding is said, not a crash";
}

} // namespace
} // namespace mocap
