// Crash recovery end to end (issue 31): the studio's window, in a process of its own, is given
// edits of every kind (head reference markers, a cleaning step applied, a rig bound and solved
// and a weight curve edited, an actor made from a neutral frame (its file then gone), the
// Retarget section's map with a gain edited, a reference video with an offset, a layout plan with
// a size picked);
// the autosave timer writes them; the process is killed with SIGKILL (nothing cleaned up); a new
// window accepts the recovery offer and every part of the session is back as the killed process
// reported it. The recovered window is left as a picture in build/tests to look at.
#include "coded_image.h"
#include "job_waits.h"
#include "sample_files.h"
#include "../core/test_support.h"

#include "actions/actor_actions.h"
#include "actions/reference_marker_actions.h"
#include "actions/weight_edit_actions.h"
#include "dialogs/retarget_map_chooser.h"
#include "document/autosave.h"
#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/layout_plan_model.h"
#include "document/reference_video.h"
#include "document/reference_videos.h"
#include "document/retarget_map_model.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "main_window.h"
#include "panels/blendshape_solve_panel.h"
#include "panels/cleaning_panel.h"
#include "panels/layout_planning_panel.h"
#include "panels/retarget_section.h"
#include "sample_window.h"
#include "views/layout_error_plot.h"
#include "views/vtk_viewport.h"

#include "mocap/model/provenance.h"

#include <opencv2/videoio.hpp>

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMessageBox>
#include <QProcess>
#include <QProcessEnvironment>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>

#include <gtest/gtest.h>

#include <iostream>
#include <memory>

#include <signal.h>
#include <sys/types.h>

namespace mocap {
namespace {

/// Set in the child's environment: the folder it works in (its take copy, its video).
constexpr char kChildFolderVariable[] = "MOCAP_KILL_RECOVERY_CHILD";
/// The line the child prints once the autosave holds every edit: this prefix, then the facts.
constexpr char kFactsPrefix[] = "kill-recovery-facts: ";
const std::vector<std::string> kReferenceRoots = {"root-1", "root-2", "root-3", "root-4"};
constexpr Eigen::Index kEditedShape = 1;
constexpr Eigen::Index kEditFirst = 100;
constexpr Eigen::Index kEditLast = 400;

QString sampleFile(const char* name)
{
  return QString::fromUtf8(checkout::sampleDir()) + QLatin1Char('/') + QLatin1String(name);
}

QJsonArray jsonLabels(const std::vector<std::string>& labels)
{
  QJsonArray array;
  for (const std::string& label : labels)
    array.append(QString::fromStdString(label));
  return array;
}

/// Samples a cleaning step made or moved (filled, edited, smoothed), over every marker.
Eigen::Index cleanedSamples(const Take& take)
{
  Eigen::Index n = 0;
  for (const StateCounts& c : stateCounts(take))
    n += c.filled + c.edited + c.smoothed;
  return n;
}

/// What a session holds, as the killed process and the recovered window each report it.
QJsonObject sessionFacts(studio::MainWindow& window)
{
  ui::StudioSession& session = window.session();
  const Take& take = session.document().take();
  const ui::BlendshapeSolveModel& weights = session.blendshapes();
  QJsonObject facts;
  facts[QStringLiteral("cleaned")] = static_cast<qint64>(cleanedSamples(take));
  facts[QStringLiteral("history")] = static_cast<int>(take.history().size());
  facts[QStringLiteral("reference")] = jsonLabels(session.document().referenceLabels());
  facts[QStringLiteral("boundMarkers")] = static_cast<int>(session.faceMesh().binding().markers.size());
  facts[QStringLiteral("rig")] = weights.rigPath();
  facts[QStringLiteral("frames")] = static_cast<qint64>(weights.weights().rows());
  facts[QStringLiteral("weightSum")] = weights.weights().sum();
  facts[QStringLiteral("editedCurveSum")] =  // the edited shape over the edited range
      weights.hasResult() ? weights.weights().col(kEditedShape).segment(kEditFirst, kEditLast - kEditFirst + 1).sum()
                          : -1.0;
  facts[QStringLiteral("lambda")] = weights.result().lambda;
  facts[QStringLiteral("method")] = static_cast<int>(weights.solvedWith().method);
  QJsonArray selected;
  for (const Eigen::Index shape : weights.selectedShapes())
    selected.append(static_cast<qint64>(shape));
  facts[QStringLiteral("selectedShapes")] = selected;
  const ui::ReferenceVideo* video = session.referenceVideos().current();
  facts[QStringLiteral("video")] = video ? video->path() : QString();
  facts[QStringLiteral("videoOffset")] = video ? video->offset() : -1.0;
  facts[QStringLiteral("videoOpen")] = video && video->isOpen();
  facts[QStringLiteral("layoutSize")] = static_cast<qint64>(session.layoutPlan().selectedSize());
  facts[QStringLiteral("layoutLabels")] = jsonLabels(session.layoutPlan().selectedLabels());
  const ui::LayoutPlanResult* plan = session.layoutPlan().result();
  facts[QStringLiteral("layoutSizes")] = plan ? static_cast<int>(plan->plan.sizes.size()) : 0;
  facts[QStringLiteral("actor")] = weights.actor() ? QString::fromStdString(weights.actor()->name) : QString();
  const ui::RetargetMapModel& map = weights.retargetMap();
  facts[QStringLiteral("mapName")] = map.name();
  facts[QStringLiteral("mapEdited")] = map.edited();
  facts[QStringLiteral("mapGain")] = map.map() ? map.map()->channels.front().sources.front().gain : -1.0;
  const ui::RetargetSection& section = *window.blendshapeSolvePanel()->retargetSection();
  facts[QStringLiteral("mapRows")] = section.table()->rowCount();
  facts[QStringLiteral("mapChoice")] =
      QString::fromStdString(section.findChild<ui::RetargetMapChooser*>()->map().value_or("(none)"));
  return facts;
}

/// The child: edits of every kind in a studio window, the autosave timer at its shortest, then
/// the facts on stdout, and nothing more until it is killed.
void runStudioUntilKilled(const QString& folder)
{
  const QString take = folder + QStringLiteral("/take.c3d");
  const QString video = folder + QStringLiteral("/hmc.avi");
  ASSERT_TRUE(QFile::copy(test::qpath(test::sampleTake()), take));  // its video sidecar goes beside it
  ASSERT_TRUE(test::writeCodedVideo(video.toStdString(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0, 200, 96, 64));
  auto window = std::make_unique<studio::MainWindow>();
  window->resize(1280, 900);
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  ASSERT_EQ(window->openFile(take, true), QString());
  ui::TakeDocument& document = window->document();
  ui::StudioSession& session = window->session();

  std::vector<Eigen::Index> roots;
  for (const std::string& label : kReferenceRoots)
    roots.push_back(*document.take().markerIndex(label));
  ASSERT_TRUE(window->referenceMarkerActions()->change(roots));

  ui::CleaningPanel& cleaning = *window->cleaningPanel();
  test::waitForPreview(cleaning);
  ASSERT_GT(cleaning.apply(), 0);

  ASSERT_EQ(window->loadRig(sampleFile("ict_face_rig.glb"), {}, sampleFile("Facial-Sing.ict_face_rig.binding.json"), true),
            QString());
  session.blendshapes().setSelectedShapes({kEditedShape});
  document.setRange(kEditFirst, kEditLast);
  ASSERT_EQ(window->blendshapeSolvePanel()->edits().scale(0.5), QString());

  // An actor from the current frame, loaded; its file then gone, so only the session state has it.
  document.setCurrentFrame(40);
  ASSERT_EQ(window->blendshapeSolvePanel()->actors().newFromNeutralFrame(folder + QStringLiteral("/anna.json")), QString());
  ASSERT_TRUE(QFile::remove(folder + QStringLiteral("/anna.json")));
  ui::RetargetSection& retarget = *window->blendshapeSolvePanel()->retargetSection();
  ASSERT_EQ(retarget.loadMap(std::string("ict_to_arkit")), QString());
  ASSERT_EQ(retarget.setGain(0, 0.5), QString());

  ASSERT_EQ(window->openReferenceVideo(video, 0.52), QString());

  ui::LayoutPlanningPanel& layout = *window->layoutPlanningPanel();
  ui::LayoutPlanParameters quick = layout.parameters();
  quick.restarts = 5;
  quick.minK = 3;
  quick.maxK = 12;
  quick.randomSubsets = 2;
  layout.setParameters(quick);
  ASSERT_EQ(layout.run(), QString());
  ASSERT_TRUE(test::waitForJob(layout.jobs()));
  ASSERT_NE(session.layoutPlan().result(), nullptr) << layout.statusText().toStdString();
  const std::vector<Eigen::Index>& sizes = layout.plot()->selectableSizes();
  ASSERT_GE(sizes.size(), 2u);
  const Eigen::Index picked = sizes.front() == layout.plot()->recommendedSize() ? sizes[1] : sizes.front();
  ASSERT_TRUE(layout.plot()->setSelectedSize(picked));  // not the recommended size: the pick must come back
  ASSERT_EQ(session.layoutPlan().selectedSize(), picked);

  // The second write after this point began after every edit.
  QSignalSpy written(window->autosave(), &ui::Autosave::written);
  window->autosave()->setInterval(1000);
  while (written.count() < 2)
    ASSERT_TRUE(written.wait(60000)) << "no autosave";
  std::cout << kFactsPrefix << QJsonDocument(sessionFacts(*window)).toJson(QJsonDocument::Compact).toStdString()
            << std::endl;
  for (;;)
    QTest::qWait(1000);
}

/// Starts this test program as the child and waits for its facts; empty after a failure.
QJsonObject startStudioAndWaitForAutosave(QProcess& child, const QString& folder)
{
  QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
  environment.insert(QString::fromLatin1(kChildFolderVariable), folder);
  child.setProcessEnvironment(environment);
  child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
  child.start(QCoreApplication::applicationFilePath(), {QStringLiteral("--gtest_filter=KillAndRecover.*")});
  QElapsedTimer clock;
  clock.start();
  QByteArray output;
  while (clock.elapsed() < 300000 && child.state() != QProcess::NotRunning) {
    (void)child.waitForReadyRead(1000);
    output += child.readAllStandardOutput();
    const qsizetype at = output.indexOf(kFactsPrefix);
    const qsizetype end = at < 0 ? -1 : output.indexOf('\n', at);
    if (end > at)
      return QJsonDocument::fromJson(output.mid(at + static_cast<qsizetype>(sizeof kFactsPrefix) - 1, end - at))
          .object();
  }
  ADD_FAILURE() << "the studio did not autosave its edits:\n" << output.toStdString();
  return {};
}

TEST(KillAndRecover, EveryPartOfTheSessionComesBackAfterTheStudioIsKilled)
{
  if (qEnvironmentVariableIsSet(kChildFolderVariable)) {
    runStudioUntilKilled(qEnvironmentVariable(kChildFolderVariable));
    return;  // only after a failure: the parent then finds no facts
  }
  test::TempDir dir;
  QSettings().clear();  // the child reads the same settings: the defaults, as a first run
  QDir(ui::Autosave::defaultFolder()).removeRecursively();
  QProcess child;
  const QJsonObject before = startStudioAndWaitForAutosave(child, test::qpath(dir.path()));
  ASSERT_FALSE(before.isEmpty());
  ASSERT_EQ(::kill(static_cast<pid_t>(child.processId()), SIGKILL), 0);
  ASSERT_TRUE(child.waitForFinished(10000));
  EXPECT_EQ(child.exitStatus(), QProcess::CrashExit);
  ASSERT_EQ(ui::Autosave::leftovers().size(), 1u) << "the killed studio's recovery file";

  auto window = std::make_unique<studio::MainWindow>();
  window->resize(1280, 900);
  window->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
  test::whenModal<QMessageBox>([](QMessageBox* box) { box->button(QMessageBox::Yes)->click(); });
  ASSERT_TRUE(window->offerRecovery());
  EXPECT_TRUE(window->document().isModified()) << "recovered edits are unsaved";
  const QJsonObject after = sessionFacts(*window);

  EXPECT_GT(before[QStringLiteral("cleaned")].toInteger(), 0);
  EXPECT_GE(before[QStringLiteral("history")].toInt(), 1);
  EXPECT_EQ(before[QStringLiteral("reference")].toArray(), jsonLabels(kReferenceRoots));
  EXPECT_GT(before[QStringLiteral("boundMarkers")].toInt(), 0);
  EXPECT_GT(before[QStringLiteral("frames")].toInteger(), 0);
  EXPECT_TRUE(before[QStringLiteral("videoOpen")].toBool());
  EXPECT_GE(before[QStringLiteral("layoutSizes")].toInt(), 2);
  EXPECT_GT(before[QStringLiteral("editedCurveSum")].toDouble(), 0.0) << "the edit halved a curve that moves there";
  EXPECT_EQ(before[QStringLiteral("actor")].toString(), QStringLiteral("anna"));
  EXPECT_TRUE(before[QStringLiteral("mapEdited")].toBool());
  EXPECT_DOUBLE_EQ(before[QStringLiteral("mapGain")].toDouble(), 0.5);
  EXPECT_GT(before[QStringLiteral("mapRows")].toInt(), 0);
  EXPECT_EQ(before[QStringLiteral("mapChoice")].toString(), QStringLiteral("ict_to_arkit"));
  for (auto it = before.begin(); it != before.end(); ++it)
    EXPECT_EQ(after.value(it.key()), it.value()) << it.key().toStdString() << " did not come back";
  EXPECT_EQ(window->statusBar()->currentMessage().contains(QStringLiteral("not restored")), false)
      << window->statusBar()->currentMessage().toStdString();

  // Left to look at: the recovered window with its docks.
  QTest::qWait(500);
  const QImage shot = ui::grabWithViewports(*window);
  EXPECT_FALSE(shot.isNull());
  (void)shot.save(QDir(QString::fromUtf8(checkout::testBuildDir())).filePath(QStringLiteral("kill_recovery.png")));
  window->document().undoStack()->setClean();  // close without asking
  QDir(ui::Autosave::defaultFolder()).removeRecursively();
}

} // namespace
} // namespace mocap
