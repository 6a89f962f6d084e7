// The hand-off from the studio: Export Rig writes the solved rig as FBX or glTF through the same
// writer and options as `mocap solve -o` (retarget map, key reduction, axes), reports the keys kept
// and remembers its choices; a map that does not fit the rig is refused before anything is
// written; a Live Link Face recording opens as the loaded rig's curves, undoably, and exports with
// its own rate and timecode, as `mocap convert REC.csv OUT.fbx --rig RIG` writes it.
#include "sample_files.h"
#include "../core/test_support.h"

#include "main_window.h"
#include "sample_window.h"

#include "dialogs/rig_export_dialog.h"
#include "document/blendshape_solve_model.h"
#include "document/take_document.h"
#include "panels/blendshape_solve_panel.h"
#include "panels/retarget_section.h"
#include "views/mapped_curve_plot.h"
#include "views/weight_curve_view.h"

#include "mocap/base/file_io.h"
#include "mocap/io/live_link_face_csv.h"
#include "mocap/io/live_link_face_map.h"
#include "mocap/io/live_link_face_resample.h"
#include "mocap/io/retarget_map_io.h"
#include "mocap/io/rig_io.h"
#include "mocap/io/weight_output.h"

#include <QAction>
#include <QApplication>
#include <QPushButton>
#include <QTableWidget>
#include <QTest>
#include <QSettings>
#include <QTimer>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

namespace mocap {
namespace {

using ui::RigExportDialog;
using ui::RigExportFormat;

/// Curves that move slowly against 0.01 weight units, so reduction has keys to drop.
Eigen::MatrixXd smoothWeights(Eigen::Index frames, Eigen::Index shapes)
{
  Eigen::MatrixXd weights(frames, shapes);
  for (Eigen::Index f = 0; f < frames; ++f)
    for (Eigen::Index s = 0; s < shapes; ++s)
      weights(f, s) = 0.5 + 0.5 * std::sin(0.03 * static_cast<double>((s + 1) * f));
  return weights;
}

/// A map onto two channels of another rig: JawOpen at half the jaw, BrowUp from the brow.
std::string writeTwoChannelMap(const test::TempDir& dir)
{
  const std::string path = dir.file("two.json").string();
  std::ofstream(path) << R"({"format": "mocap retarget map", "version": 1, "channels": [
  {"name": "JawOpen", "sources": [{"shape": "jawOpen", "gain": 0.5}]},
  {"name": "BrowUp", "sources": [{"shape": "browInnerUp"}], "min": 0, "max": 1}]})";
  return path;
}

struct RigFixture
{
  RigFixture()
  {
    QSettings().clear();
    test::writeSmallRig(dir);
    source.rig = std::make_shared<const BlendshapeRig>(
        readRig(dir.file("neutral.obj"), dir.file("shapes")));
    source.weights = smoothWeights(240, source.rig->shapeCount());
    source.frameRate = 60.0;
    source.firstFrame = 1;
    source.baseName = QStringLiteral("take");
  }
  ~RigFixture() { QSettings().clear(); }

  QString path(const char* name) const { return QString::fromStdString(dir.file(name).string()); }

  test::TempDir dir;
  ui::RigExportSource source;
};

TEST(RigExport, WritesTheFbxTheCommandLineWritesWithTheMapAndReducedKeys)
{
  RigFixture fx;
  const std::string map = writeTwoChannelMap(fx.dir);
  RigExportDialog dialog(fx.source);
  dialog.setFormat(RigExportFormat::Fbx);
  dialog.setOutputPath(fx.path("rig.fbx"));
  dialog.setMap(QString::fromStdString(map));
  dialog.setReduction(0.01);
  dialog.setUpAxis(FbxUpAxis::Z);
  dialog.setUnits(LengthUnit::Millimetre);
  ASSERT_EQ(dialog.exportNow(), QString()) << dialog.statusText().toStdString();

  // As `mocap solve -o OUT.fbx --map MAP --reduce 0.01 --up z --units mm` writes it.
  WeightOutput cli;
  cli.map = map;
  cli.frameRate = 60.0;
  cli.firstFrame = 1;
  cli.reduce = 0.01;
  cli.fbx.up = FbxUpAxis::Z;
  cli.fbx.unit = LengthUnit::Millimetre;
  const std::optional<KeyCount> expected = writeWeightOutput(fx.dir.file("cli.fbx"), *fx.source.rig, fx.source.weights, cli);
  const std::string written = readFileBytes(fx.dir.file("rig.fbx"));
  EXPECT_EQ(written, readFileBytes(fx.dir.file("cli.fbx")));
  EXPECT_NE(written.find("JawOpen"), std::string::npos);
  EXPECT_EQ(written.find("mouthSmile_L"), std::string::npos) << "only the map's channels are written";

  // The keys: two curves of 240 frames, fewer kept, within the tolerance, and said so.
  ASSERT_TRUE(dialog.lastKeys().has_value());
  ASSERT_TRUE(expected.has_value());
  EXPECT_EQ(dialog.lastKeys()->before, 2 * 240);
  EXPECT_EQ(dialog.lastKeys()->after, expected->after);
  EXPECT_LT(dialog.lastKeys()->after, dialog.lastKeys()->before / 2);
  EXPECT_LE(dialog.lastKeys()->maxError, 0.01 + 1e-12);
  EXPECT_TRUE(dialog.statusText().contains(QStringLiteral("Kept %1 of 480 keys").arg(expected->after)))
      << dialog.statusText().toStdString();
}

TEST(RigExport, AMapThatDoesNotFitTheRigIsRefusedBeforeWriting)
{
  RigFixture fx;
  RigExportDialog dialog(fx.source);
  dialog.setFormat(RigExportFormat::Fbx);
  dialog.setOutputPath(fx.path("rig.fbx"));
  dialog.setMap(QStringLiteral("ict_to_arkit"));  // ICT's split shapes: the small rig lacks them
  EXPECT_TRUE(dialog.statusText().contains(QStringLiteral("cannot be used"))) << dialog.statusText().toStdString();
  EXPECT_FALSE(dialog.exportNow().isEmpty());
  EXPECT_FALSE(std::filesystem::exists(fx.dir.file("rig.fbx")));
  dialog.setMap(QString::fromStdString(fx.dir.file("missing.json").string()));
  EXPECT_FALSE(dialog.exportNow().isEmpty());
  EXPECT_FALSE(std::filesystem::exists(fx.dir.file("rig.fbx")));
}

TEST(RigExport, RemembersFormatMapReductionAndFolder)
{
  RigFixture fx;
  const std::string map = writeTwoChannelMap(fx.dir);
  std::filesystem::create_directories(fx.dir.file("out"));
  {
    RigExportDialog dialog(fx.source);
    dialog.setFormat(RigExportFormat::Glb);
    dialog.setOutputPath(fx.path("out/anything.glb"));
    dialog.setMap(QString::fromStdString(map));
    dialog.setReduction(0.02);
    ASSERT_EQ(dialog.exportNow(), QString()) << dialog.statusText().toStdString();
    EXPECT_EQ(readFileBytes(fx.dir.file("out/anything.glb")).substr(0, 4), "glTF");
    ASSERT_TRUE(dialog.lastKeys().has_value());  // glTF: the key frames all curves share
    EXPECT_LT(dialog.lastKeys()->after, 240);
  }
  RigExportDialog again(fx.source);
  EXPECT_EQ(again.format(), RigExportFormat::Glb);
  EXPECT_EQ(again.map(), std::optional<std::string>(map));
  EXPECT_EQ(again.reduction(), std::optional<double>(0.02));
  EXPECT_EQ(again.outputPath(), fx.path("out/take.glb"));
  again.setFormat(RigExportFormat::WeightsCsv);
  EXPECT_EQ(again.reduction(), std::nullopt) << "a CSV has no keys to reduce";
  EXPECT_EQ(again.outputPath(), fx.path("out/take.csv"));
}

TEST(RigExport, OffersTheRetargetSectionsMapAsEditedAndWritesThroughIt)
{
  RigFixture fx;
  const std::string file = writeTwoChannelMap(fx.dir);
  RetargetMap edited = readRetargetMap(file);
  edited.channels[0].sources[0].gain = 2.0;  // as typed in the section's table, not saved
  fx.source.sectionMap = edited;
  fx.source.sectionMapName = QString::fromStdString(file);
  fx.source.sectionMapEdited = true;
  {
    RigExportDialog dialog(fx.source);
    EXPECT_TRUE(dialog.sectionMapChosen()) << "the section's map is chosen when there is one";
    EXPECT_EQ(dialog.map(), std::nullopt);
    dialog.setFormat(RigExportFormat::WeightsCsv);
    dialog.setOutputPath(fx.path("studio.csv"));
    ASSERT_EQ(dialog.exportNow(), QString()) << dialog.statusText().toStdString();
    // As `mocap solve --map EDITED.json -o OUT.csv` writes it once the edited map is saved.
    writeRetargetMap(fx.dir.file("edited.json"), edited);
    WeightOutput cli;
    cli.map = fx.dir.file("edited.json").string();
    cli.frameRate = 60.0;
    cli.firstFrame = 1;
    (void)writeWeightOutput(fx.dir.file("cli.csv"), *fx.source.rig, fx.source.weights, cli);
    EXPECT_EQ(readFileBytes(fx.dir.file("studio.csv")), readFileBytes(fx.dir.file("cli.csv")));
    cli.map = file;  // the gains as read: another file
    (void)writeWeightOutput(fx.dir.file("unedited.csv"), *fx.source.rig, fx.source.weights, cli);
    EXPECT_NE(readFileBytes(fx.dir.file("studio.csv")), readFileBytes(fx.dir.file("unedited.csv")));
    // The section's map does not fit a Live Link Face CSV (its names are not the app's): said at once.
    dialog.setFormat(RigExportFormat::LiveLinkCsv);
    EXPECT_TRUE(dialog.statusText().contains(QStringLiteral("cannot be used"))) << dialog.statusText().toStdString();
    dialog.setFormat(RigExportFormat::WeightsCsv);
    dialog.setMap(QStringLiteral("ict_identity"));
    EXPECT_FALSE(dialog.sectionMapChosen());
    dialog.chooseSectionMap();
    EXPECT_TRUE(dialog.sectionMapChosen());
  }
  // The section's map is not remembered as the choice: without one, the last other choice is back.
  fx.source.sectionMap.reset();
  RigExportDialog again(fx.source);
  EXPECT_FALSE(again.sectionMapChosen());
  EXPECT_EQ(again.map(), std::nullopt);
}

class LiveLinkInStudioTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    test::writeSmallRig(dir);
    window = test::openSampleWindow(1280, 800);
    ASSERT_NE(window, nullptr);
    panel = window->blendshapeSolvePanel();
    ASSERT_NE(panel, nullptr);
    ASSERT_EQ(window->loadRig(QString::fromStdString(dir.file("neutral.obj").string()),
                              QString::fromStdString(dir.file("shapes").string())),
              QString());
  }

  ui::BlendshapeSolveModel& model() const { return panel->model(); }

  test::TempDir dir;
  std::unique_ptr<studio::MainWindow> window;
  ui::BlendshapeSolvePanel* panel = nullptr;
};

TEST_F(LiveLinkInStudioTest, ARecordingOpensAsTheRigsCurvesAtTheTakesRateUndoablyAndExportsWithItsTimecode)
{
  const std::filesystem::path csv = test::dataFile("livelink_face/alex_rom_4_first200.csv");
  const LiveLinkFaceRecording recorded = readLiveLinkFaceCsv(csv);
  const double takeRate = window->document().take().frameRate();
  ASSERT_NE(liveLinkFaceRate(recorded), takeRate) << "the sample take is not at the recording's 30 Hz";
  // Its rows meet the take's frames: resampled to the take's rate by its timecodes.
  const LiveLinkFaceRecording recording = resampleLiveLinkFace(recorded, takeRate);
  ASSERT_EQ(panel->openLiveLinkRecording(QString::fromStdString(csv.string())), QString())
      << panel->statusText().toStdString();
  ASSERT_TRUE(model().hasResult());
  ASSERT_EQ(model().weights().rows(), static_cast<Eigen::Index>(recording.timecodes.size()));
  // The rig's jawOpen is the recording's JawOpen (arkit_to_ict by name), sample by sample.
  const auto& names = liveLinkFaceShapeNames();
  const auto jaw = std::find(names.begin(), names.end(), "JawOpen") - names.begin();
  EXPECT_LT((model().weights().col(1) - recording.weights.col(jaw)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_GT(model().weights().col(1).maxCoeff(), model().weights().col(1).minCoeff()) << "the jaw moves";
  EXPECT_TRUE(panel->statusText().contains(QStringLiteral("%1 sample").arg(recording.timecodes.size())))
      << panel->statusText().toStdString();
  EXPECT_TRUE(panel->statusText().contains(QStringLiteral("Recorded at 30 Hz: resampled"))) << panel->statusText().toStdString();

  // Exports are at the take's rate from the recording's first timecode: the FBX `mocap convert`
  // writes of the resampled recording.
  const ui::RigExportSource source = panel->exportSource();
  EXPECT_DOUBLE_EQ(source.frameRate, takeRate);
  ASSERT_TRUE(source.startSeconds.has_value());
  EXPECT_DOUBLE_EQ(*source.startSeconds, liveLinkFaceSeconds(recorded.timecodes.front()));
  RigExportDialog dialog(source);
  dialog.setFormat(RigExportFormat::Fbx);
  dialog.setMap({});
  dialog.setReduction(std::nullopt);
  dialog.setUpAxis(FbxUpAxis::Y);
  dialog.setUnits(LengthUnit::Centimetre);
  dialog.setOutputPath(QString::fromStdString(dir.file("studio.fbx").string()));
  ASSERT_EQ(dialog.exportNow(), QString()) << dialog.statusText().toStdString();
  WeightOutput cli;  // as convertRecording sets it
  cli.frameRate = takeRate;
  cli.startSeconds = liveLinkFaceSeconds(recorded.timecodes.front());
  (void)writeWeightOutput(dir.file("cli.fbx"), *model().rig(),
                          liveLinkFaceWeightsOnRig(recording.weights, model().rig()->shapeNames(), std::nullopt), cli);
  EXPECT_EQ(readFileBytes(dir.file("studio.fbx")), readFileBytes(dir.file("cli.fbx")));
  cli.startSeconds.reset();
  (void)writeWeightOutput(dir.file("from0.fbx"), *model().rig(),
                          liveLinkFaceWeightsOnRig(recording.weights, model().rig()->shapeNames(), std::nullopt), cli);
  EXPECT_NE(readFileBytes(dir.file("studio.fbx")), readFileBytes(dir.file("from0.fbx"))) << "the timecode is kept";

  // Undo puts back no curves, redo the recording's.
  QUndoStack* stack = window->document().undoStack();
  stack->undo();
  EXPECT_FALSE(model().hasResult());
  EXPECT_FALSE(model().readCurves().has_value());
  stack->redo();
  ASSERT_EQ(model().weights().rows(), static_cast<Eigen::Index>(recording.timecodes.size()));
  EXPECT_TRUE(model().readCurves().has_value());
}

TEST_F(LiveLinkInStudioTest, ARecordingKeepsItsHeadTurnInTheLiveLinkExport)
{
  // The sample recording holds its head still: give it a turn, at the take's own rate.
  LiveLinkFaceRecording recording = readLiveLinkFaceCsv(test::dataFile("livelink_face/alex_rom_4_first200.csv"));
  recording = resampleLiveLinkFace(recording, window->document().take().frameRate());
  for (Eigen::Index r = 0; r < recording.rotations.rows(); ++r)
    recording.rotations.row(r).head<3>() << 0.001 * static_cast<double>(r), -0.2, 0.05 * std::sin(0.1 * static_cast<double>(r));
  const std::string csv = dir.file("turning.csv").string();
  writeLiveLinkFaceCsv(csv, recording);
  ASSERT_EQ(panel->openLiveLinkRecording(QString::fromStdString(csv)), QString()) << panel->statusText().toStdString();
  EXPECT_FALSE(panel->statusText().contains(QStringLiteral("resampled"))) << "already at the take's rate";

  RigExportDialog dialog(panel->exportSource());
  dialog.setFormat(RigExportFormat::LiveLinkCsv);
  dialog.setMap({});
  dialog.setOutputPath(QString::fromStdString(dir.file("out.csv").string()));
  ASSERT_EQ(dialog.exportNow(), QString()) << dialog.statusText().toStdString();
  const LiveLinkFaceRecording written = readLiveLinkFaceCsv(dir.file("out.csv"));
  ASSERT_EQ(written.rotations.rows(), recording.rotations.rows());
  EXPECT_LT((written.rotations.leftCols(3) - recording.rotations.leftCols(3)).cwiseAbs().maxCoeff(), 1e-9)
      << "HeadYaw, HeadPitch, HeadRoll as recorded";
  ASSERT_GT(recording.rotations.rightCols(6).cwiseAbs().maxCoeff(), 0.05) << "the real recording's eyes move";
  EXPECT_LT((written.rotations.rightCols(6) - recording.rotations.rightCols(6)).cwiseAbs().maxCoeff(), 1e-9)
      << "each eye's yaw, pitch and roll as recorded, not zeros";
}

TEST_F(LiveLinkInStudioTest, AMapOrFileThatDoesNotFitChangesNothing)
{
  const QString csv = QString::fromStdString(test::dataFile("livelink_face/alex_rom_4_first200.csv").string());
  const int edits = window->document().undoStack()->count();
  EXPECT_FALSE(panel->openLiveLinkRecording(csv, std::string("ict_to_arkit")).isEmpty())
      << "ict_to_arkit reads ICT shapes, not the recording's curves";
  EXPECT_FALSE(model().hasResult());
  const std::string notRecording = dir.file("weights.csv").string();
  std::ofstream(notRecording) << "Frame,Time,jawOpen\n1,0,0.5\n";
  EXPECT_TRUE(panel->openLiveLinkRecording(QString::fromStdString(notRecording)).contains(QStringLiteral("Cannot open")));
  EXPECT_FALSE(model().hasResult());
  EXPECT_EQ(window->document().undoStack()->count(), edits);
}

TEST_F(LiveLinkInStudioTest, TheDocksExportRigButtonOpensExportRig)
{
  const QString csv = QString::fromStdString(test::dataFile("livelink_face/alex_rom_4_first200.csv").string());
  ASSERT_EQ(panel->openLiveLinkRecording(csv), QString());
  QPushButton* button = nullptr;
  for (QPushButton* candidate : panel->findChildren<QPushButton*>())
    if (candidate->text() == QStringLiteral("Export Rig…"))
      button = candidate;
  ASSERT_NE(button, nullptr);
  ASSERT_TRUE(button->isEnabled());
  bool opened = false;
  QTimer::singleShot(0, [&opened] {  // runs inside the dialog's exec()
    QWidget* modal = QApplication::activeModalWidget();
    auto* dialog = qobject_cast<RigExportDialog*>(modal);
    opened = dialog != nullptr && dialog->format() == RigExportFormat::Fbx;
    if (modal)
      modal->close();
  });
  button->click();
  EXPECT_TRUE(opened);
  // File ▸ Export Rig… opens the same dialog.
  QAction* fileExport = nullptr;
  for (QAction* action : window->findChildren<QAction*>())
    if (action->text() == QStringLiteral("Export Ri&g…"))
      fileExport = action;
  ASSERT_NE(fileExport, nullptr);
  opened = false;
  QTimer::singleShot(0, [&opened] {
    QWidget* modal = QApplication::activeModalWidget();
    opened = qobject_cast<RigExportDialog*>(modal) != nullptr;
    if (modal)
      modal->close();
  });
  fileExport->trigger();
  EXPECT_TRUE(opened);
}

TEST_F(LiveLinkInStudioTest, RetargetSectionEditsGainsUndoablyAndShowsTheMappedCurves)
{
  const QString csv = QString::fromStdString(test::dataFile("livelink_face/alex_rom_4_first200.csv").string());
  ASSERT_EQ(panel->openLiveLinkRecording(csv), QString());
  ui::RetargetSection* section = panel->retargetSection();
  ASSERT_NE(section, nullptr);
  // A shipped map for other names does not fit the small rig: said by the map's line.
  ASSERT_EQ(section->loadMap(std::string("ict_to_arkit")), QString());
  EXPECT_TRUE(section->statusText().contains(QStringLiteral("does not fit"))) << section->statusText().toStdString();
  EXPECT_FALSE(section->mapped().has_value());

  ASSERT_EQ(section->loadMap(writeTwoChannelMap(dir)), QString()) << section->statusText().toStdString();
  ASSERT_EQ(section->table()->rowCount(), 2);
  ASSERT_TRUE(section->mapped().has_value());
  const Eigen::VectorXd jaw = model().weights().col(1);
  EXPECT_LT((section->mapped()->weights.col(0) - 0.5 * jaw).cwiseAbs().maxCoeff(), 1e-12);
  section->selectRow(0);
  EXPECT_LT((section->plot()->mapped() - 0.5 * jaw).cwiseAbs().maxCoeff(), 1e-12) << "the plot shows the channel";

  // A gain typed in the table: one undoable step; the mapped curve and the plot follow.
  QUndoStack* stack = window->document().undoStack();
  section->table()->item(0, 2)->setText(QStringLiteral("2"));
  EXPECT_LT((section->mapped()->weights.col(0) - 2.0 * jaw).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((section->plot()->mapped() - 2.0 * jaw).cwiseAbs().maxCoeff(), 1e-12);
  section->table()->item(0, 2)->setText(QStringLiteral("not a gain"));
  EXPECT_EQ(section->table()->item(0, 2)->text(), QStringLiteral("2")) << "a bad entry is put back";
  stack->undo();
  EXPECT_EQ(section->table()->item(0, 2)->text(), QStringLiteral("0.5"));
  EXPECT_LT((section->mapped()->weights.col(0) - 0.5 * jaw).cwiseAbs().maxCoeff(), 1e-12);
  stack->redo();

  // Export Rig offers the map as edited, before it is saved.
  const ui::RigExportSource source = panel->exportSource();
  ASSERT_TRUE(source.sectionMap.has_value());
  EXPECT_DOUBLE_EQ(source.sectionMap->channels[0].sources[0].gain, 2.0);
  EXPECT_TRUE(source.sectionMapEdited);
  EXPECT_TRUE(RigExportDialog(source).sectionMapChosen());

  // Saved with the edited gain, for Export Rig and mocap solve --map.
  const std::string saved = dir.file("edited.json").string();
  ASSERT_EQ(section->saveMap(QString::fromStdString(saved)), QString());
  EXPECT_DOUBLE_EQ(readRetargetMap(saved).channels[0].sources[0].gain, 2.0);
  EXPECT_FALSE(panel->exportSource().sectionMapEdited);
}

TEST_F(LiveLinkInStudioTest, TheWeightsViewDrawsTheMapsChannelsWhileAMapIsLoaded)
{
  const QString csv = QString::fromStdString(test::dataFile("livelink_face/alex_rom_4_first200.csv").string());
  ASSERT_EQ(panel->openLiveLinkRecording(csv), QString());
  ui::WeightCurveView* view = window->weightView();
  ASSERT_NE(view, nullptr);
  ASSERT_TRUE(window->showDock(QStringLiteral("weightsDock")));
  view->resize(1000, 300);
  view->repaint();
  EXPECT_FALSE(view->showsMappedCurves());
  ui::RetargetSection* section = panel->retargetSection();
  ASSERT_EQ(section->loadMap(std::string("ict_to_arkit")), QString());
  EXPECT_FALSE(view->showsMappedCurves()) << "a map that does not fit the rig: its shapes are drawn";

  ASSERT_EQ(section->loadMap(writeTwoChannelMap(dir)), QString());
  ASSERT_TRUE(view->showsMappedCurves());
  view->repaint();
  // JawOpen (half the rig's jaw) where it stands furthest from BrowUp.
  const Eigen::MatrixXd mapped = section->mapped()->weights;
  Eigen::Index frame = 0;
  (void)(mapped.col(0) - mapped.col(1)).cwiseAbs().maxCoeff(&frame);
  ASSERT_GT(std::abs(mapped(frame, 0) - mapped(frame, 1)), 0.1);
  const std::optional<QPointF> point = view->pointOf(0, frame);
  ASSERT_TRUE(point.has_value());
  EXPECT_EQ(view->shapeAt(*point), 0);
  EXPECT_TRUE(view->readoutAt(*point).startsWith(QStringLiteral("JawOpen"))) << view->readoutAt(*point).toStdString();
  EXPECT_TRUE(view->readoutAt(*point).endsWith(QString::number(mapped(frame, 0), 'f', 3)))
      << view->readoutAt(*point).toStdString();
  // A click on the channel selects the shape it takes, so the weight edits act on it.
  QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, point->toPoint());
  EXPECT_EQ(model().selectedShapes(), std::vector<Eigen::Index>{1}) << "jawOpen feeds JawOpen";

  // A gain edited in the section moves the channel's curve; no map: the shapes again.
  Eigen::Index open = 0;
  (void)mapped.col(0).maxCoeff(&open);
  ASSERT_GT(mapped(open, 0), 0.02);  // the recording opens the jaw a little: 0.036 after the map
  const std::optional<QPointF> before = view->pointOf(0, open);
  ASSERT_EQ(section->setGain(0, 1.5), QString());
  const std::optional<QPointF> moved = view->pointOf(0, open);
  ASSERT_TRUE(before.has_value() && moved.has_value());
  EXPECT_LT(moved->y(), before->y() - 1.0) << "three times as high: drawn higher";
  ASSERT_EQ(section->loadMap(std::nullopt), QString());
  EXPECT_FALSE(view->showsMappedCurves());
}

} // namespace
} // namespace mocap
