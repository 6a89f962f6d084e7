// The session's models without a window (issue 31): the take's reference videos with their
// sidecar, and the layout plan with its highlight, owned by a StudioSession alone (no MainWindow,
// no dock): what the Reference Video and Layout planning docks only show; and the session's state
// (what crash recovery keeps beside the take) saved, encoded and restored into a new session.
#include "../core/coded_video.h"
#include "../core/test_support.h"
#include "sample_files.h"

#include "checkout_paths.h"
#include "commands/edit_weights_command.h"
#include "commands/remove_markers_command.h"
#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/layout_plan_model.h"
#include "document/reference_video.h"
#include "document/reference_videos.h"
#include "document/studio_session.h"
#include "document/session_files.h"
#include "document/session_state.h"
#include "document/take_document.h"

#include "mocap/base/error.h"
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

/// The sample (copied to `take`, so a video sidecar goes beside the copy) solved to the bundled ICT
/// rig through its binding, as `mocap review --solve` loads it.
void loadSolvedSample(ui::StudioSession& session, const std::filesystem::path& take)
{
  std::filesystem::copy_file(test::sampleTake(), take);
  ui::SessionFiles files;
  files.take = QString::fromStdString(take.string());
  files.rig = QString::fromUtf8(checkout::sampleDir()) + QStringLiteral("/ict_face_rig.glb");
  files.binding = QString::fromUtf8(checkout::sampleDir()) + QStringLiteral("/Facial-Sing.ict_face_rig.binding.json");
  files.solve = true;
  ASSERT_EQ(ui::loadSessionFiles(session, files), QString());
  ASSERT_TRUE(session.blendshapes().hasResult());
}

TEST(SessionRecovery, RestoresEveryPartOfTheSessionStraightFromItsState)
{
  test::TempDir dir;
  ASSERT_TRUE(test::writeCodedVideo(dir.file("hmc.avi"), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0, 50, 96, 64));
  ui::StudioSession crashed;
  ASSERT_NO_FATAL_FAILURE(loadSolvedSample(crashed, dir.file("take.c3d")));
  ui::BlendshapeSolveModel& weights = crashed.blendshapes();
  // A weight edit (undoable, on the one stack) and a picked shape: the edited curve is what comes back.
  crashed.undoStack()->push(new ui::EditWeightsCommand(weights, QStringLiteral("Scale"), {3}, 100,
                                                       Eigen::MatrixXd::Constant(20, 1, 0.625)));
  weights.setSelectedShapes({3, 7});
  ASSERT_EQ(crashed.referenceVideos().open(sessionModelsPath(dir.file("hmc.avi"))), QString());
  crashed.referenceVideos().current()->setOffset(0.52);
  crashed.layoutPlan().setResult(twoMarkerPlan(), 2);

  const QByteArray bytes = ui::encodeSessionState(crashed.saveState());
  const ui::SessionState state = ui::decodeSessionState(bytes, "state");
  ui::StudioSession recovered;
  recovered.document().setTake(crashed.document().take());
  EXPECT_TRUE(recovered.saveState().rigPath.isEmpty()) << "a new take starts without the rig";
  ASSERT_EQ(recovered.restoreState(state), QString());

  EXPECT_EQ(recovered.faceMesh().meshPath(), crashed.faceMesh().meshPath());
  ASSERT_EQ(recovered.faceMesh().binding().markers.size(), crashed.faceMesh().binding().markers.size());
  EXPECT_EQ(recovered.faceMesh().binding().markers.front().label, crashed.faceMesh().binding().markers.front().label);
  EXPECT_NE(recovered.faceMesh().rig(), nullptr) << recovered.faceMesh().error().toStdString();
  const ui::BlendshapeSolveModel& back = recovered.blendshapes();
  EXPECT_EQ(back.rigPath(), weights.rigPath());
  ASSERT_TRUE(back.hasResult());
  EXPECT_EQ(back.weights(), weights.weights()) << "every curve as it was, edits included";
  EXPECT_DOUBLE_EQ(back.weights()(110, 3), 0.625);
  EXPECT_EQ(back.result().held, weights.result().held);
  EXPECT_EQ(back.solvedWith().method, weights.solvedWith().method);
  EXPECT_EQ(back.solvedWith().neutralFrame, weights.solvedWith().neutralFrame);
  EXPECT_DOUBLE_EQ(back.result().lambda, weights.result().lambda);
  EXPECT_EQ(back.selectedShapes(), (std::vector<Eigen::Index>{3, 7}));
  ASSERT_EQ(recovered.referenceVideos().count(), 1);
  EXPECT_EQ(recovered.referenceVideos().at(0).path(), sessionModelsPath(dir.file("hmc.avi")));
  EXPECT_DOUBLE_EQ(recovered.referenceVideos().at(0).offset(), 0.52);
  ASSERT_NE(recovered.layoutPlan().result(), nullptr);
  EXPECT_EQ(recovered.layoutPlan().selectedSize(), 2);
  EXPECT_EQ(recovered.layoutPlan().captureLabels(), crashed.layoutPlan().captureLabels());

  // Damage is said, never a crash: cut bytes, foreign bytes, a rig file gone.
  EXPECT_THROW((void)ui::decodeSessionState(bytes.left(bytes.size() / 2), "cut"), FormatError);
  EXPECT_THROW((void)ui::decodeSessionState(QByteArray(64, '\x7f'), "foreign"), FormatError);
  ui::SessionState gone = state;
  gone.rigPath = sessionModelsPath(dir.file("moved.glb"));
  gone.meshPath = gone.rigPath;
  ui::StudioSession partly;
  partly.document().setTake(crashed.document().take());
  const QString problems = partly.restoreState(gone);
  EXPECT_TRUE(problems.contains(QStringLiteral("moved.glb"))) << problems.toStdString();
  EXPECT_FALSE(partly.blendshapes().hasResult()) << "no curves without their rig";
  EXPECT_EQ(partly.referenceVideos().count(), 1) << "what can be restored still is";
  EXPECT_NE(partly.layoutPlan().result(), nullptr);
}

} // namespace
} // namespace mocap
