// Scenes built from a session, with no widget (issue 31), under Xvfb: a session loaded from the
// sample's files alone renders the posed blendshape rig and the face mesh beside the markers off
// screen; `mocap review --solve --binding` draws them, and without a display says so instead of
// aborting; the review of a frame is the studio's view of it, pixel for pixel, with the rig and
// mesh layers; and Reset Camera keeps a walking body's every marker in the view, whatever the
// view's shape.
#include "../core/test_support.h"

#include "image_difference.h"
#include "main_window.h"
#include "sample_window.h"

#include "dialogs/review_export.h"
#include "document/blendshape_solve_model.h"
#include "document/session_files.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "mocap/model/marker_points.h"
#include "mocap/video/video_source.h"
#include "views/marker_view_3d.h"
#include "views/review_scene.h"
#include "views/vtk_viewport.h"
#include "checkout_paths.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTest>
#include <QVBoxLayout>

#include <gtest/gtest.h>

#include <cmath>

namespace mocap {
namespace {

const QString kSample = QString::fromUtf8(checkout::sampleDir());
const QString kRig = kSample + QStringLiteral("/ict_face_rig.glb");
const QString kRigBinding = kSample + QStringLiteral("/Facial-Sing.ict_face_rig.binding.json");
const QSize kReviewSize(640, 360);

/// Pixels in the posed rig's warm skin tone (BlendshapeScene: 236, 196, 160, however lit): neither
/// the background, the grey face mesh, nor any marker state colour (the filled orange is redder).
qsizetype rigColoured(const QImage& image)
{
  qsizetype count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      if (c.red() < 60)
        continue;
      const double g = c.greenF() / c.redF(), b = c.blueF() / c.redF();
      if (std::abs(g - 196.0 / 236.0) < 0.07 && std::abs(b - 160.0 / 236.0) < 0.09)
        ++count;
    }
  return count;
}

ui::SessionFiles sampleWithRig()
{
  ui::SessionFiles files;
  files.take = QString::fromStdString(test::sampleTake().string());
  files.rig = kRig;
  files.binding = kRigBinding;
  files.solve = true;
  return files;
}

TEST(ReviewScene, DrawsTheSolvedRigOfASessionLoadedFromFiles)
{
  ui::StudioSession session;
  ASSERT_EQ(ui::loadSessionFiles(session, sampleWithRig()), QString());
  ASSERT_TRUE(session.blendshapes().hasResult());
  ui::ReviewSource source;
  source.session = &session;
  source.resetCamera = true;
  ui::ReviewScene scene(source, kReviewSize);
  ASSERT_TRUE(scene.usable()) << scene.failureReason().toStdString();
  scene.frameCamera(1000, 1000);
  const QImage withRig = scene.render(1000);
  ASSERT_FALSE(withRig.isNull());
  EXPECT_EQ(withRig.size(), kReviewSize);
  EXPECT_TRUE(QApplication::topLevelWidgets().isEmpty()) << "rendered off screen, with no widget";
  EXPECT_EQ(session.document().currentFrame(), 0) << "the session's own frame stays";

  source.settings.rigShown = false;
  ui::ReviewScene markersAndMesh(source, kReviewSize);
  markersAndMesh.frameCamera(1000, 1000);
  const QImage withoutRig = markersAndMesh.render(1000);
  const qsizetype total = qsizetype(withRig.width()) * withRig.height();
  EXPECT_GT(rigColoured(withRig), total / 50) << "the posed rig covers a good part of the picture";
  EXPECT_LT(rigColoured(withoutRig), total / 1000) << "nothing else is drawn in the rig's colour";
  EXPECT_GT(test::compareImages(withRig, withoutRig).fraction(), 0.02);
}

TEST(ReviewScene, BadFilesGiveAnErrorNamingTheFile)
{
  ui::StudioSession session;
  ui::SessionFiles files = sampleWithRig();
  files.binding = kSample + QStringLiteral("/missing.binding.json");
  EXPECT_TRUE(ui::loadSessionFiles(session, files).contains(QStringLiteral("missing.binding.json")));
  files.binding.clear();
  EXPECT_TRUE(ui::loadSessionFiles(session, files).contains(QStringLiteral("--binding")))
      << "a solve without a binding says what is missing";
}

TEST(ReviewScene, MocapReviewWithSolveAndBindingDrawsTheRig)
{
  test::TempDir dir;
  const QString out = QString::fromStdString(dir.file("rig.avi").string());
  QProcess mocap;
  mocap.start(QString::fromUtf8(checkout::cliProgram()),
              {QStringLiteral("review"), QString::fromStdString(test::sampleTake().string()), QStringLiteral("-o"), out,
               QStringLiteral("--frames"), QStringLiteral("1001:1002"), QStringLiteral("--size"),
               QStringLiteral("640x360"), QStringLiteral("--solve"), kRig, QStringLiteral("--binding"), kRigBinding,
               QStringLiteral("--json")});
  ASSERT_TRUE(mocap.waitForFinished(180000));
  ASSERT_EQ(mocap.exitCode(), 0) << mocap.readAllStandardError().toStdString();
  const QJsonObject report = QJsonDocument::fromJson(mocap.readAllStandardOutput()).object();
  EXPECT_EQ(report.value(QStringLiteral("frames")).toInt(), 2);
  EXPECT_GT(report.value(QStringLiteral("first_frame_seconds")).toDouble(), 0.0);
  VideoSource video(report.value(QStringLiteral("output")).toString().toStdString());
  const VideoImage frame = video.frame(0);
  const QImage image(frame.rgb.data(), frame.width, frame.height, frame.width * 3, QImage::Format_RGB888);
  EXPECT_GT(rigColoured(image), qsizetype(frame.width) * frame.height / 50) << "the solved rig is drawn";
}

TEST(ReviewScene, MocapReviewWithoutADisplaySaysSoInsteadOfAborting)
{
  test::TempDir dir;
  const QString review = QFileInfo(QString::fromUtf8(checkout::cliProgram())).dir().filePath(QStringLiteral("mocap-review"));
  QProcess process;
  QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
  environment.remove(QStringLiteral("DISPLAY"));
  environment.remove(QStringLiteral("QT_QPA_PLATFORM"));
  process.setProcessEnvironment(environment);
  process.start(review, {QString::fromStdString(test::sampleTake().string()), QStringLiteral("-o"),
                         QString::fromStdString(dir.file("none.avi").string()), QStringLiteral("--frames"),
                         QStringLiteral("1001:1002")});
  ASSERT_TRUE(process.waitForFinished(60000));
  EXPECT_EQ(process.exitStatus(), QProcess::NormalExit) << "no crash, no abort";
  EXPECT_EQ(process.exitCode(), 1);
  EXPECT_TRUE(process.readAllStandardError().contains("DISPLAY"));
  EXPECT_EQ(test::entryCount(dir.path()), 0u);
}

TEST(ReviewScene, IsTheStudiosViewWithTheMeshAndRigLayers)
{
  const auto window = test::openSampleWindow(1280, 800);
  ASSERT_NE(window, nullptr);
  ASSERT_EQ(window->loadRig(kRig, {}, kRigBinding, true), QString());
  ui::VtkViewport* viewport = window->markerView()->viewport();
  viewport->setFixedSize(kReviewSize);
  window->document().setCurrentFrame(1000);
  window->markerView()->resetCamera();
  QTest::qWait(300);
  const QImage studio = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB888);
  ASSERT_GT(rigColoured(studio), qsizetype(kReviewSize.width()) * kReviewSize.height() / 50) << "the studio draws the rig";
  ui::ReviewScene scene(window->reviewSource(), kReviewSize);
  const QImage review = scene.render(1000);
  EXPECT_TRUE(test::matchesImage(review, studio, QStringLiteral("ReviewSceneWithRig")));
  EXPECT_EQ(window->document().currentFrame(), 1000);
}

/// Every marker of the current frame is drawn inside `view`'s viewport.
void expectEveryMarkerInView(const ui::MarkerView3d& view, const ui::TakeDocument& document, const char* when)
{
  const QRectF inside(QPointF(0, 0), QSizeF(view.viewport()->size()));
  int drawn = 0;
  for (const Eigen::Index m : markerPoints(document.take())) {
    if (!document.take().isValid(document.currentFrame(), m))
      continue;
    const auto at = view.screenPosition(m);
    ASSERT_TRUE(at) << document.take().label(m);
    EXPECT_TRUE(inside.contains(*at)) << when << ": " << document.take().label(m) << " at " << at->x() << ", "
                                      << at->y() << " outside " << inside.width() << " x " << inside.height();
    ++drawn;
  }
  EXPECT_GT(drawn, 10);
}

TEST(ReviewScene, ResetCameraKeepsAWalkingBodyInView)
{
  ui::TakeDocument document;
  ASSERT_EQ(document.open(QString::fromStdString(test::dataFile("c3d/sample00_motion_analysis/Walk1.c3d").string())),
            QString());
  QWidget host;
  auto* layout = new QVBoxLayout(&host);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* view = new ui::MarkerView3d(document, &host);
  layout->addWidget(view);
  host.resize(900, 500);
  host.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&host));
  for (const Eigen::Index frame : {Eigen::Index(0), document.take().frameCount() / 2}) {
    document.setCurrentFrame(frame);
    view->resetCamera();
    QTest::qWait(100);
    expectEveryMarkerInView(*view, document, "landscape");
  }
  // The window changes shape before anyone moves the camera: framed again for the new shape.
  host.resize(400, 700);
  QTest::qWait(200);
  expectEveryMarkerInView(*view, document, "resized to portrait");
}

} // namespace
} // namespace mocap
