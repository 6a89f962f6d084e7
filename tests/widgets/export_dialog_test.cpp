// Export Animation dialog: a PC2 export holds exactly the source's frames, a BVH export parses with
// every marker and frame, a cancelled export leaves nothing, and the mesh formats wait for a mesh;
// File ▸ Export… to .fbx goes through it, so its FBX gets the same options as the command line's.
#include "job_waits.h"
#include "../core/test_support.h"

#include "actions/take_file_actions.h"
#include "dialogs/export_dialog.h"
#include "document/studio_options.h"
#include "document/take_document.h"
#include "main_window.h"

#include "mocap/base/file_io.h"
#include "mocap/io/fbx_writer.h"
#include "mocap/model/take_slice.h"
#include "mocap/io/obj_io.h"
#include "mocap/io/pc2_io.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QCoreApplication>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTimer>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <sstream>
#include <thread>

namespace mocap {
namespace {

namespace fs = std::filesystem;
using ui::AnimationFormat;
using ui::ExportDialog;

// Three markers moving along x with the frame, numbered from frame 101.
Take movingTake()
{
  Take take({"nose", "chin", "brow"}, 30, 60.0);
  take.setFirstFrame(101);
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
      take.setPosition(f, m, Eigen::Vector3d(0.5 * static_cast<double>(f) + static_cast<double>(m), 10.0 * static_cast<double>(m), 3.0));
      take.valid()(f, m) = true;
    }
  return take;
}

Mesh triangle()
{
  Mesh mesh;
  mesh.vertices.resize(3, 3);
  mesh.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  mesh.faces.push_back({{0, 1, 2}, {}, {}});
  return mesh;
}

// The triangle at take frame index f: moved by (f, −f/2, 0.25) and its last vertex lifted by f/10.
MeshVertices movedTriangle(Eigen::Index f)
{
  MeshVertices v = triangle().vertices;
  v.rowwise() += Eigen::RowVector3d(static_cast<double>(f), -0.5 * static_cast<double>(f), 0.25);
  v(2, 2) += static_cast<double>(f) / 10.0;
  return v;
}

struct Fixture
{
  Fixture()
  {
    QSettings().clear();
    document.setTake(movingTake(), QString::fromStdString(dir.file("take.c3d").string()));
  }
  ~Fixture() { QSettings().clear(); }

  test::TempDir dir;
  ui::TakeDocument document;
};

TEST(ExportDialog, PointCacheHoldsTheSourceFramesOfTheRange)
{
  Fixture fx;
  ExportDialog dialog(fx.document);
  dialog.setMeshSource(triangle(), [](Eigen::Index f, MeshVertices& v) { v = movedTriangle(f); },
                       QStringLiteral("tri"));
  dialog.setFormat(AnimationFormat::ObjPlusPc2);
  ASSERT_EQ(dialog.format(), AnimationFormat::ObjPlusPc2);
  const fs::path cache = fx.dir.file("anim.pc2");
  dialog.setOutputPath(QString::fromStdString(cache.string()));
  dialog.setFrameRange(104, 113);  // take frame indices 3..12
  QSignalSpy finished(&dialog, &ExportDialog::exportFinished);
  ASSERT_TRUE(dialog.startExport()) << dialog.statusText().toStdString();
  ASSERT_TRUE(test::waitForJob(dialog.jobs()));
  ASSERT_EQ(finished.count(), 1);
  EXPECT_TRUE(finished.at(0).at(0).toBool()) << dialog.statusText().toStdString();

  const PointCache read = readPc2(cache);
  EXPECT_FLOAT_EQ(read.startFrame, 104.0f);
  ASSERT_EQ(read.samples.size(), 10u);
  for (Eigen::Index s = 0; s < 10; ++s)
    EXPECT_EQ(read.samples[static_cast<std::size_t>(s)], movedTriangle(3 + s).cast<float>()) << "sample " << s;
  EXPECT_EQ(readObj(fx.dir.file("anim.obj")).vertices, triangle().vertices);
  EXPECT_TRUE(dialog.statusText().contains(QStringLiteral("10"))) << dialog.statusText().toStdString();
}

TEST(ExportDialog, ObjSequenceWritesOneFilePerFrame)
{
  Fixture fx;
  ExportDialog dialog(fx.document);
  dialog.setMeshSource(triangle(), [](Eigen::Index f, MeshVertices& v) { v = movedTriangle(f); },
                       QStringLiteral("tri"));
  dialog.setFormat(AnimationFormat::ObjSequence);
  dialog.setOutputPath(QString::fromStdString(fx.dir.file("frames").string()));
  dialog.setFrameRange(101, 103);
  ASSERT_TRUE(dialog.startExport()) << dialog.statusText().toStdString();
  ASSERT_TRUE(test::waitForJob(dialog.jobs()));
  EXPECT_EQ(test::entryCount(fx.dir.file("frames")), 3u);
  EXPECT_EQ(readObj(fx.dir.file("frames/tri_0003.obj")).vertices, movedTriangle(2));
}

// What a whitespace-splitting BVH reader needs: joint names, the frame count and one row of
// 6 + 3 · #markers numbers per frame.
TEST(ExportDialog, BvhOfTheMarkersParsesWithEveryMarkerAndFrame)
{
  Fixture fx;
  ExportDialog dialog(fx.document);
  dialog.setFormat(AnimationFormat::Bvh);
  const fs::path bvh = fx.dir.file("take.bvh");
  dialog.setOutputPath(QString::fromStdString(bvh.string()));
  dialog.setFrameRange(111, 130);
  ASSERT_TRUE(dialog.startExport()) << dialog.statusText().toStdString();
  ASSERT_TRUE(test::waitForJob(dialog.jobs()));

  std::istringstream in(readFileBytes(bvh));
  std::vector<std::string> joints;
  long frames = -1;
  std::vector<std::vector<double>> rows;
  for (std::string token; in >> token;) {
    if (token == "JOINT") {
      in >> token;
      joints.push_back(token);
    } else if (token == "Frames:") {
      in >> frames;
    } else if (token == "Time:") {
      in >> token;
      for (std::string line; std::getline(in, line);) {
        std::istringstream numbers(line);
        std::vector<double> row;
        for (double x; numbers >> x;)
          row.push_back(x);
        if (!row.empty())
          rows.push_back(row);
      }
    }
  }
  EXPECT_EQ(joints, (std::vector<std::string>{"nose", "chin", "brow"}));
  ASSERT_EQ(frames, 20);
  ASSERT_EQ(rows.size(), 20u);
  const Take& take = fx.document.take();
  for (std::size_t r = 0; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), 6u + 9u);
    // No head poses: each marker's channels are its position, frame 111 being index 10.
    const Eigen::Vector3d chin = take.position(10 + static_cast<Eigen::Index>(r), 1);
    EXPECT_NEAR(rows[r][9], chin.x(), 1e-6);
    EXPECT_NEAR(rows[r][10], chin.y(), 1e-6);
    EXPECT_NEAR(rows[r][11], chin.z(), 1e-6);
  }
}

TEST(ExportDialog, CancellingMidExportLeavesNoPartialCache)
{
  Fixture fx;
  ExportDialog dialog(fx.document);
  std::atomic<int> calls{0};
  dialog.setMeshSource(triangle(),
                       [&calls](Eigen::Index f, MeshVertices& v) {
                         ++calls;
                         std::this_thread::sleep_for(std::chrono::milliseconds(20));
                         v = movedTriangle(f);
                       },
                       QStringLiteral("tri"));
  dialog.setFormat(AnimationFormat::ObjPlusPc2);
  dialog.setOutputPath(QString::fromStdString(fx.dir.file("anim.pc2").string()));
  QSignalSpy finished(&dialog, &ExportDialog::exportFinished);
  dialog.show();
  ASSERT_TRUE(dialog.startExport());
  EXPECT_TRUE(dialog.isRunning());
  EXPECT_FALSE(dialog.startExport());  // one export at a time
  while (calls < 3)
    QCoreApplication::processEvents();
  dialog.reject();  // Escape or Cancel while running: stops the export, keeps the dialog
  ASSERT_TRUE(test::waitForJob(dialog.jobs()));
  EXPECT_TRUE(dialog.isVisible());
  ASSERT_EQ(finished.count(), 1);
  EXPECT_FALSE(finished.at(0).at(0).toBool());
  EXPECT_LT(calls.load(), 30);  // it stopped early
  EXPECT_TRUE(dialog.statusText().contains(QStringLiteral("cancelled"))) << dialog.statusText().toStdString();
  EXPECT_EQ(test::entryCount(fx.dir.path()), 0u);  // no cache, no OBJ, no temporary file
}

TEST(ExportDialog, MeshFormatsWaitForAMeshAndBadPathsAreExplained)
{
  Fixture fx;
  ExportDialog dialog(fx.document);
  auto* combo = dialog.findChild<QComboBox*>();
  ASSERT_NE(combo, nullptr);
  const auto* model = qobject_cast<QStandardItemModel*>(combo->model());
  const QStandardItem* pc2 = model->item(combo->findData(static_cast<int>(AnimationFormat::ObjPlusPc2)));
  EXPECT_FALSE(pc2->isEnabled());
  EXPECT_TRUE(pc2->toolTip().contains(QStringLiteral("face mesh"))) << pc2->toolTip().toStdString();
  dialog.setFormat(AnimationFormat::ObjPlusPc2);
  EXPECT_EQ(dialog.format(), AnimationFormat::Bvh);
  EXPECT_TRUE(dialog.outputPath().endsWith(QStringLiteral("take.bvh"))) << dialog.outputPath().toStdString();

  dialog.setOutputPath(QString::fromStdString(fx.dir.file("missing/take.bvh").string()));
  EXPECT_FALSE(dialog.startExport());
  EXPECT_TRUE(dialog.statusText().contains(QStringLiteral("does not exist"))) << dialog.statusText().toStdString();
  dialog.setFrameRange(120, 110);
  dialog.setOutputPath(QString::fromStdString(fx.dir.file("take.bvh").string()));
  EXPECT_FALSE(dialog.startExport());
  EXPECT_TRUE(dialog.statusText().contains(QStringLiteral("after"))) << dialog.statusText().toStdString();
  EXPECT_FALSE(fs::exists(fx.dir.file("take.bvh")));

  dialog.setMeshSource(triangle(), [](Eigen::Index, MeshVertices& v) { v = triangle().vertices; }, {});
  EXPECT_TRUE(pc2->isEnabled());
}

TEST(ExportDialog, FbxOfTheMarkersIsWhatConvertWritesWithItsKeysReported)
{
  Fixture fx;
  ExportDialog dialog(fx.document);
  dialog.setFormat(AnimationFormat::Fbx);
  ASSERT_EQ(dialog.format(), AnimationFormat::Fbx) << "the markers need no mesh";
  dialog.setFbxOptions(FbxUpAxis::Y, 0.1);
  dialog.setOutputPath(QString::fromStdString(fx.dir.file("markers").string()));
  EXPECT_EQ(dialog.outputPath(), QString::fromStdString(fx.dir.file("markers").string()));
  dialog.setFormat(AnimationFormat::Bvh);
  dialog.setFormat(AnimationFormat::Fbx);  // the extension follows the format
  ASSERT_EQ(dialog.outputPath(), QString::fromStdString(fx.dir.file("markers.fbx").string()));
  dialog.setFrameRange(101, 120);
  ASSERT_TRUE(dialog.startExport()) << dialog.statusText().toStdString();
  ASSERT_TRUE(test::waitForJob(dialog.jobs()));
  // As `mocap convert TAKE OUT.fbx --up y --reduce 0.1` writes the 20 frames (the take is in mm).
  KeyCount counted;
  const std::string expected =
      markersFbx(sliceFrames(fx.document.take(), 0, 20), FbxUpAxis::Y, FbxCurveKeys{0.1, &counted});
  EXPECT_EQ(readFileBytes(fx.dir.file("markers.fbx")), expected);
  EXPECT_EQ(counted.before, 3 * 3 * 20);
  EXPECT_LT(counted.after, counted.before / 4) << "straight lines keep their ends";
  EXPECT_TRUE(dialog.statusText().contains(QStringLiteral("Kept %1 of %2 keys").arg(counted.after).arg(counted.before)))
      << dialog.statusText().toStdString();
  // Remembered: the next dialog opens on FBX with the same options.
  ExportDialog again(fx.document);
  EXPECT_EQ(again.format(), AnimationFormat::Fbx);
}

// Maya and MotionBuilder work in centimetres: the markers are written in the units chosen, as
// `mocap convert TAKE OUT.fbx --units cm` writes them, the key tolerance staying in millimetres.
TEST(ExportDialog, FbxInTheUnitsChosenIsWhatConvertWritesWithThoseUnits)
{
  Fixture fx;
  ExportDialog dialog(fx.document);
  dialog.setFormat(AnimationFormat::Fbx);
  dialog.setFbxOptions(FbxUpAxis::Z, 0.1);
  dialog.setMarkerUnits(LengthUnit::Centimetre);
  dialog.setOutputPath(QString::fromStdString(fx.dir.file("markers_cm.fbx").string()));
  dialog.setFrameRange(101, 120);
  ASSERT_TRUE(dialog.startExport()) << dialog.statusText().toStdString();
  ASSERT_TRUE(test::waitForJob(dialog.jobs()));
  Take centimetres = sliceFrames(fx.document.take(), 0, 20);
  ASSERT_EQ(centimetres.units(), LengthUnit::Millimetre);
  centimetres.convertUnits(LengthUnit::Centimetre);
  EXPECT_EQ(readFileBytes(fx.dir.file("markers_cm.fbx")), markersFbx(centimetres, FbxUpAxis::Z, FbxCurveKeys{0.1 / millimetresPer(LengthUnit::Centimetre)}));
  EXPECT_EQ(fx.document.take().units(), LengthUnit::Millimetre) << "the take itself is not converted";
  dialog.setMarkerUnits(std::nullopt);  // the take's own units write what the take holds
  dialog.setOutputPath(QString::fromStdString(fx.dir.file("markers_mm.fbx").string()));
  ASSERT_TRUE(dialog.startExport()) << dialog.statusText().toStdString();
  ASSERT_TRUE(test::waitForJob(dialog.jobs()));
  EXPECT_EQ(readFileBytes(fx.dir.file("markers_mm.fbx")),
            markersFbx(sliceFrames(fx.document.take(), 0, 20), FbxUpAxis::Z, FbxCurveKeys{0.1}));
}

TEST(ExportDialog, RemembersTheLastFolderAndFormat)
{
  Fixture fx;
  fs::create_directories(fx.dir.file("out"));
  {
    ExportDialog dialog(fx.document);
    dialog.setMeshSource(triangle(), [](Eigen::Index f, MeshVertices& v) { v = movedTriangle(f); }, {});
    dialog.setFormat(AnimationFormat::ObjPlusPc2);
    dialog.setOutputPath(QString::fromStdString(fx.dir.file("out/anim.pc2").string()));
    dialog.setFrameRange(101, 102);
    ASSERT_TRUE(dialog.startExport());
    ASSERT_TRUE(test::waitForJob(dialog.jobs()));
  }
  ExportDialog again(fx.document);
  EXPECT_EQ(again.format(), AnimationFormat::Bvh);  // no mesh yet: the mesh formats are off
  again.setMeshSource(triangle(), [](Eigen::Index, MeshVertices& v) { v = triangle().vertices; }, {});
  EXPECT_EQ(again.format(), AnimationFormat::ObjPlusPc2);
  EXPECT_EQ(again.outputPath(), QString::fromStdString(fx.dir.file("out/take.pc2").string()));
}

TEST(ExportDialog, FileMenuExportAnimationOpensItWithItsOwnShortcut)
{
  QSettings().clear();
  studio::MainWindow window;
  const QKeySequence keys(Qt::CTRL | Qt::SHIFT | Qt::Key_E);
  QAction* exportAnimation = nullptr;
  int sameKeys = 0;
  for (QAction* action : window.findChildren<QAction*>()) {
    if (action->text() == QStringLiteral("Export Ani&mation…"))
      exportAnimation = action;
    sameKeys += action->shortcut() == keys ? 1 : 0;
  }
  ASSERT_NE(exportAnimation, nullptr);
  EXPECT_EQ(exportAnimation->shortcut(), keys);
  EXPECT_EQ(sameKeys, 1);
  bool opened = false;
  QTimer::singleShot(0, [&opened] {  // runs inside the dialog's exec()
    QWidget* modal = QApplication::activeModalWidget();
    opened = qobject_cast<ui::ExportDialog*>(modal) != nullptr;
    if (modal)
      modal->close();
  });
  exportAnimation->trigger();
  EXPECT_TRUE(opened);
  QSettings().clear();
}

TEST(ExportDialog, FileExportToFbxOpensItOnFbxSoTheKeysCanBeReducedAndAreReported)
{
  Fixture fx;
  ui::StudioOptions options;
  QWidget parent;
  ui::TakeFileActions files(fx.document, options, parent);
  // Another format is written at once, as before.
  files.exportTo(QString::fromStdString(fx.dir.file("copy.trc").string()));
  EXPECT_TRUE(fs::exists(fx.dir.file("copy.trc")));

  const QString path = QString::fromStdString(fx.dir.file("chosen.fbx").string());
  bool onFbx = false;
  QString status;
  QTimer::singleShot(0, [&] {  // runs inside the dialog's exec()
    auto* dialog = qobject_cast<ExportDialog*>(QApplication::activeModalWidget());
    if (dialog == nullptr)
      return;
    onFbx = dialog->format() == AnimationFormat::Fbx && dialog->outputPath() == path;
    dialog->setFbxOptions(FbxUpAxis::Z, 0.1);
    if (dialog->startExport() && test::waitForJob(dialog->jobs()))
      status = dialog->statusText();
    dialog->close();
  });
  files.exportTo(path);
  EXPECT_TRUE(onFbx) << "File > Export... to .fbx opens Export Animation on FBX with the chosen file";
  // As `mocap convert TAKE OUT.fbx --up z --reduce 0.1` writes it, the keys kept said.
  KeyCount counted;
  EXPECT_EQ(readFileBytes(fx.dir.file("chosen.fbx")),
            markersFbx(fx.document.take(), FbxUpAxis::Z, FbxCurveKeys{0.1, &counted}));
  EXPECT_LT(counted.after, counted.before);
  EXPECT_TRUE(status.contains(QStringLiteral("Kept %1 of %2 keys").arg(counted.after).arg(counted.before)))
      << status.toStdString();
}

} // namespace
} // namespace mocap
