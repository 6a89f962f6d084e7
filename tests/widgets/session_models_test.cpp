// The session's models without a window (issue 31): the take's reference videos with their
// sidecar, and the layout plan with its highlight, owned by a StudioSession alone (no MainWindow,
// no dock): what the Reference Video and Layout planning docks only show; and the session's state
// (what crash recovery keeps beside the take) saved, encoded and restored into a new session.
#include "../core/coded_video.h"
#include "../core/test_support.h"
#include "sample_files.h"

#include "checkout_paths.h"
#include "commands/edit_retarget_gain_command.h"
#include "commands/edit_weights_command.h"
#include "commands/remove_markers_command.h"
#include "document/autosave.h"
#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/layout_plan_model.h"
#include "document/reference_video.h"
#include "document/reference_videos.h"
#include "document/retarget_map_model.h"
#include "document/studio_session.h"
#include "document/session_files.h"
#include "document/session_state.h"
#include "document/take_document.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/deform/actor_calibration.h"
#include "mocap/io/take_io.h"
#include "mocap/video/reference_video_sidecar.h"

#include <opencv2/videoio.hpp>

#include <QDataStream>
#include <QDateTime>
#include <QFile>
#include <QSettings>
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

/// An actor profile of the solved sample's bound markers at frame 40 (as Actor ▸ New from Neutral
/// Frame makes it), and the session's curves marked as solved with it.
std::shared_ptr<const ActorProfile> sampleActor(ui::StudioSession& session)
{
  const ui::FaceMeshModel& face = session.faceMesh();
  ui::BlendshapeSolveModel& weights = session.blendshapes();
  std::vector<std::string> bound;
  for (const MarkerBinding& marker : face.binding().markers)
    bound.push_back(marker.label);
  const Take& take = face.rigTake();
  auto actor = std::make_shared<const ActorProfile>(makeActorProfile(
      "anna", face.binding(), *weights.rig(), neutralFromFrame(take, bound, take.firstFrame() + 40), take.units(),
      "take.c3d:40"));
  BlendshapeSolveOptions options = weights.solvedWith();
  options.actor = actor;
  BlendshapeSolveResult result = weights.result();
  EXPECT_TRUE(weights.setResult(std::move(result), options));
  return actor;
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
  // The actor the solve uses (made here, with no file: the state keeps it whole) and the Retarget
  // section's map with a gain edited.
  const std::shared_ptr<const ActorProfile> actor = sampleActor(crashed);
  weights.setActor(actor, sessionModelsPath(dir.file("anna.json")));
  ui::RetargetMapModel& map = weights.retargetMap();
  map.setMap(identityRetargetMap(weights.rig()->shapeNames()), sessionModelsPath(dir.file("identity.json")));
  crashed.undoStack()->push(new ui::EditRetargetGainCommand(map, 3, 0, 0.25, QStringLiteral("Gain")));
  ASSERT_TRUE(map.edited());

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
  ASSERT_NE(back.actor(), nullptr) << "the actor the solve used";
  EXPECT_EQ(back.actor()->name, "anna");
  EXPECT_EQ(back.actor()->neutral, actor->neutral);
  EXPECT_EQ(back.actor()->extent, actor->extent);
  EXPECT_EQ(back.actorPath(), sessionModelsPath(dir.file("anna.json")));
  ASSERT_NE(back.solvedWith().actor, nullptr) << "the curves were solved with it";
  EXPECT_EQ(back.solvedWith().actor->name, "anna");
  const ui::RetargetMapModel& mapBack = back.retargetMap();
  ASSERT_TRUE(mapBack.map().has_value()) << "the Retarget section's map";
  EXPECT_EQ(mapBack.name(), sessionModelsPath(dir.file("identity.json")));
  EXPECT_TRUE(mapBack.edited()) << "still to be saved";
  ASSERT_EQ(mapBack.map()->channels.size(), map.map()->channels.size());
  EXPECT_DOUBLE_EQ(mapBack.map()->channels[3].sources[0].gain, 0.25) << "the edited gain";
  EXPECT_EQ(mapBack.map()->channels[4].name, map.map()->channels[4].name);

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

/// The sample take opened (untitled) in a new session, as a recovered take is set.
void setSampleTake(ui::StudioSession& session)
{
  session.document().setTake(readTake(test::sampleTake().string()));
}

TEST(SessionRecovery, AStateOfVersionOneStillBringsItsFaceMeshBack)
{
  // A state with the face mesh and its binding as the version 1 encoder wrote it, field by field.
  const std::string binding = readFileBytes(test::sampleBinding().toStdString());
  QByteArray v1;
  {
    QDataStream out(&v1, QIODevice::WriteOnly);
    out.setVersion(QDataStream::Qt_6_0);
    out << quint32(0x4d535354) << quint32(1);
    out << test::sampleMesh() << QByteArray::fromStdString(binding) << QString() << QString();  // mesh, binding, rig, shapes
    // curves: weights 0 × 0, residual 0 × 1, no held frames, λ, λ chosen, iterations, seconds
    out << qint64(0) << qint64(0) << qint64(0) << qint64(1) << qint64(0) << 0.0 << false << qint32(0) << 0.0;
    // solved with: method, λ (none), μ, sparsity, scale, neutral frame (none), marker share, maximum weight
    out << qint32(2) << false << 1.0 << 0.0 << qint32(0) << false << 0.5 << 1.0;
    // read curves (none), selected shapes, videos, current video, layout plan (none), its size
    out << false << qint64(0) << qint64(0) << qint32(-1) << false << qint64(0);
  }
  const ui::SessionState state = ui::decodeSessionState(v1, "v1");
  EXPECT_EQ(state.meshPath, test::sampleMesh());
  EXPECT_EQ(state.binding, binding);
  EXPECT_EQ(state.actor, nullptr) << "version 1 has no actor";
  EXPECT_FALSE(state.retargetMap.has_value());
  // Version 2 only adds fields after version 1's: the same state encodes to the same bytes before them.
  const QByteArray v2 = ui::encodeSessionState(state);
  EXPECT_EQ(v2.mid(8, v1.size() - 8), v1.mid(8));
  EXPECT_GT(v2.size(), v1.size());

  ui::StudioSession recovered;
  setSampleTake(recovered);
  ASSERT_EQ(recovered.restoreState(state), QString());
  EXPECT_EQ(recovered.faceMesh().meshPath(), test::sampleMesh());
  EXPECT_GT(recovered.faceMesh().binding().markers.size(), 20u);

  // A later version is refused, naming it.
  QByteArray v3 = v2;
  v3[7] = 3;
  try {
    (void)ui::decodeSessionState(v3, "v3");
    ADD_FAILURE() << "a later version was read";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("version 3"), std::string::npos) << e.what();
  }
}

TEST(SessionRecovery, ARecoveryFileFromBeforeSessionStatesBringsItsFaceMeshBack)
{
  // What the studio wrote before session states (its autosave's "session provider"): the take and,
  // in the description beside it, the face mesh's file and binding and the window layout.
  test::TempDir dir;
  const QString folder = sessionModelsPath(dir.path());
  const QString take = folder + QStringLiteral("/take-2147483646.c3d");  // no such process
  ASSERT_TRUE(QFile::copy(test::qpath(test::sampleTake()), take));
  {
    QSettings description(take + QStringLiteral(".ini"), QSettings::IniFormat);
    description.setValue(QStringLiteral("original"), QStringLiteral("/takes/Facial-Sing.c3d"));
    description.setValue(QStringLiteral("written"), QDateTime::currentDateTime());
    description.setValue(QStringLiteral("session/mesh"), test::sampleMesh());
    description.setValue(QStringLiteral("session/binding"),
                         QString::fromStdString(readFileBytes(test::sampleBinding().toStdString())));
    description.setValue(QStringLiteral("session/windowState"), QByteArray("layout"));
  }
  const std::vector<ui::RecoveryFile> files = ui::Autosave::leftovers(folder);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_TRUE(files.front().statePath.isEmpty());
  const std::optional<ui::SessionState> state = ui::Autosave::readState(files.front());
  ASSERT_TRUE(state.has_value()) << "the face mesh in the description is the state";
  ui::StudioSession recovered;
  setSampleTake(recovered);
  ASSERT_EQ(recovered.restoreState(*state), QString());
  EXPECT_EQ(recovered.faceMesh().meshPath(), test::sampleMesh());
  EXPECT_GT(recovered.faceMesh().binding().markers.size(), 20u);

  // Without a mesh in it, such a file has no state to restore.
  QSettings(take + QStringLiteral(".ini"), QSettings::IniFormat).remove(QStringLiteral("session/mesh"));
  EXPECT_FALSE(ui::Autosave::readState(ui::Autosave::leftovers(folder).front()).has_value());
}

} // namespace
} // namespace mocap
