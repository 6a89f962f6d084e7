// Review videos under Xvfb: the studio's export and `mocap review` render the 3D view frame by
// frame beside a reference video the test writes (each frame shows its number as a bar code, at
// 25 fps against the sample's 100 Hz). Read back with OpenCV: the frame count, size and rate, the
// exact video frame beside each take frame, and the view half matching a screenshot of the view.
// A cancelled export leaves no file.
#include "../core/coded_video.h"
#include "../core/test_support.h"

#include "image_difference.h"
#include "main_window.h"
#include "sample_window.h"

#include "dialogs/review_export.h"
#include "document/take_document.h"
#include "mocap/base/process_list.h"
#include "mocap/video/review_frame.h"
#include "mocap/video/video_source.h"
#include "views/marker_view_3d.h"
#include "views/review_scene.h"
#include "views/vtk_viewport.h"
#include "checkout_paths.h"

#include <opencv2/videoio.hpp>

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <cstdlib>

#include <signal.h>

namespace mocap {
namespace {

constexpr double kVideoRate = 25.0;
constexpr double kOffset = 0.52;
const QSize kSize(640, 360);

std::filesystem::path writeWitnessVideo(const test::TempDir& dir)
{
  const auto path = dir.file("witness.avi");
  EXPECT_TRUE(test::writeCodedVideo(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), kVideoRate, 400, 240, 136));
  return path;
}

/// The part `rect` of a decoded frame, as an image.
QImage part(const VideoImage& frame, const PixelRect& rect)
{
  const QImage whole(frame.rgb.data(), frame.width, frame.height, frame.width * 3, QImage::Format_RGB888);
  return whole.copy(rect.x, rect.y, rect.width, rect.height);
}

Eigen::Index decodeBars(const QImage& image)
{
  // The witness video is letterboxed into its half: read the bars across the middle row.
  return test::codedFrameNumber(image.width(), image.height(), [&](int x, int y) { return qGreen(image.pixel(x, y)) > 128; });
}

Eigen::Index expectedVideoFrame(Eigen::Index takeFrame)
{
  return static_cast<Eigen::Index>(std::round((static_cast<double>(takeFrame) / 100.0 + kOffset) * kVideoRate));
}

/// Checks a review video of take frames first…last written beside the witness video.
void expectReviewVideo(const std::filesystem::path& path, Eigen::Index first, Eigen::Index last)
{
  VideoSource video(path);
  ASSERT_EQ(video.info().frames, last - first + 1);
  EXPECT_EQ(video.info().width, kSize.width());
  EXPECT_EQ(video.info().height, kSize.height());
  EXPECT_NEAR(video.info().rate, 100.0, 1e-3);
  const ReviewLayout layout = reviewLayout(kSize.width(), kSize.height(), true);
  // The witness frame is letterboxed: 240 × 136 scaled to the half's width, centred.
  const double scale = std::min(layout.video.width / 240.0, layout.video.height / 136.0);
  const int shownHeight = static_cast<int>(std::lround(136 * scale));
  const PixelRect shown{layout.video.x, (layout.video.height - shownHeight) / 2, layout.video.width, shownHeight};
  for (Eigen::Index i = 0; i < video.info().frames; ++i) {
    const VideoImage frame = video.frame(i);
    EXPECT_EQ(decodeBars(part(frame, shown)), expectedVideoFrame(first + i)) << "review frame " << i;
  }
}

TEST(ReviewExport, WritesTheViewBesideTheExactVideoFrameAndMatchesTheView)
{
  test::TempDir dir;
  const auto witness = writeWitnessVideo(dir);
  const auto window = test::openSampleWindow(1280, 800);
  ASSERT_NE(window, nullptr);
  ASSERT_EQ(window->selectLabels({QStringLiteral("section5-1")}), 1);
  // The studio's view at the size of the review's view half (a narrower review would widen the
  // copied camera, and the halves are compared with a screenshot of this view below).
  const ReviewLayout layout = reviewLayout(kSize.width(), kSize.height(), true);
  ui::VtkViewport* viewport = window->markerView()->viewport();
  viewport->setFixedSize(layout.view.width, layout.view.height);
  QTest::qWait(200);
  ui::ReviewRequest request;
  request.output = dir.file("review.mp4");
  request.size = kSize;
  request.first = 990;
  request.last = 1009;
  request.video = QString::fromStdString(witness.string());
  request.videoOffset = kOffset;
  request.takeName = "Facial-Sing";
  long long calls = 0;
  const ui::ReviewOutcome outcome = ui::exportReview(window->reviewSource(), request, [&calls](long long done, long long total) {
    ++calls;
    EXPECT_EQ(total, 20);
    EXPECT_EQ(done, calls);
    return true;
  });
  ASSERT_TRUE(outcome.done) << outcome.error.toStdString();
  EXPECT_EQ(outcome.frames, 20);
  EXPECT_EQ(window->document().currentFrame(), 0) << "the studio's own frame stays";
  std::cout << "review export: " << outcome.encoding.codec << " in " << outcome.encoding.container << ", "
            << static_cast<double>(outcome.frames) / outcome.seconds << " frames/s at 640 x 360\n";
  ASSERT_NO_FATAL_FAILURE(expectReviewVideo(outcome.encoding.path, request.first, request.last));

  // The view half of frame 1000 is what the studio's 3D view shows at that size and frame.
  window->document().setCurrentFrame(1000);
  QTest::qWait(200);
  const QImage screenshot = viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB888);
  ui::ReviewScene scene(window->reviewSource(), QSize(layout.view.width, layout.view.height));
  const QImage rendered = scene.render(1000);
  // The review is the studio's view: the same render, pixel for pixel within the baseline tolerance.
  EXPECT_TRUE(test::matchesImage(rendered, screenshot, QStringLiteral("ReviewScene")));
  const test::ImageDifference sceneDifference = test::compareImages(rendered, screenshot);
  VideoSource video(outcome.encoding.path);
  const QImage decoded = part(video.frame(10), layout.view);
  const test::ImageDifference difference = test::compareImages(decoded, screenshot);
  EXPECT_FALSE(difference.sizesDiffer);
  // H.264 blurs the markers' rims: a few per cent of the pixels, never the picture.
  EXPECT_LT(difference.fraction(), 0.03) << difference.differing << " of " << difference.total << " pixels differ";
  std::cout << "pixels differing from the view: review render " << 100.0 * sceneDifference.fraction()
            << " %, decoded frame " << 100.0 * difference.fraction() << " %\n";
  const QImage otherFrame = scene.render(100);
  EXPECT_GT(test::compareImages(otherFrame, screenshot).differing, difference.differing)
      << "the comparison tells frames apart";
}

TEST(ReviewExport, CancelledLeavesNoFile)
{
  test::TempDir dir;
  const auto window = test::openSampleWindow(1280, 800);
  ASSERT_NE(window, nullptr);
  ui::ReviewRequest request;
  request.output = dir.file("cancelled.mp4");
  request.size = kSize;
  request.first = 0;
  request.last = 99;
  const ui::ReviewOutcome outcome =
      ui::exportReview(window->reviewSource(), request, [](long long done, long long) { return done < 5; });
  EXPECT_TRUE(outcome.cancelled);
  EXPECT_FALSE(outcome.done);
  EXPECT_EQ(test::entryCount(dir.path()), 0u);
  request.last = 100000;  // past the take
  const ui::ReviewOutcome outside = ui::exportReview(window->reviewSource(), request, {});
  EXPECT_FALSE(outside.done);
  EXPECT_FALSE(outside.error.isEmpty());
  EXPECT_EQ(test::entryCount(dir.path()), 0u);
}

TEST(ReviewExport, MocapReviewWritesTheVideoItReports)
{
  test::TempDir dir;
  const auto witness = writeWitnessVideo(dir);
  const QString out = QString::fromStdString(dir.file("cli.mp4").string());
  QProcess mocap;
  mocap.start(QString::fromUtf8(checkout::cliProgram()),
              {QStringLiteral("review"), QString::fromStdString(test::sampleTake().string()), QStringLiteral("-o"), out,
               QStringLiteral("--frames"), QStringLiteral("1100:1129"), QStringLiteral("--size"), QStringLiteral("640x360"),
               QStringLiteral("--video"), QString::fromStdString(witness.string()), QStringLiteral("--offset"),
               QString::number(kOffset), QStringLiteral("--select"), QStringLiteral("section5-1"), QStringLiteral("--json")});
  ASSERT_TRUE(mocap.waitForFinished(120000));
  ASSERT_EQ(mocap.exitCode(), 0) << mocap.readAllStandardError().toStdString();
  const QJsonObject report = QJsonDocument::fromJson(mocap.readAllStandardOutput()).object();
  EXPECT_EQ(report.value(QStringLiteral("frames")).toInt(), 30);
  EXPECT_EQ(report.value(QStringLiteral("width")).toInt(), 640);
  EXPECT_DOUBLE_EQ(report.value(QStringLiteral("frame_rate")).toDouble(), 100.0);
  const std::filesystem::path written = report.value(QStringLiteral("output")).toString().toStdString();
  ASSERT_TRUE(std::filesystem::exists(written));
  // The take numbers its frames from 1: take frame 1100 is index 1099.
  ASSERT_NO_FATAL_FAILURE(expectReviewVideo(written, 1099, 1128));

  QProcess bad;
  bad.start(QString::fromUtf8(checkout::cliProgram()),
            {QStringLiteral("review"), QString::fromStdString(test::sampleTake().string()), QStringLiteral("-o"),
             QString::fromStdString(dir.file("bad.mp4").string()), QStringLiteral("--size"), QStringLiteral("641x360")});
  ASSERT_TRUE(bad.waitForFinished(60000));
  EXPECT_EQ(bad.exitCode(), 2);
  EXPECT_TRUE(bad.readAllStandardError().contains("even"));
  EXPECT_FALSE(std::filesystem::exists(dir.file("bad.mp4")));
}

/// The processes whose parent is `parent` and whose name is `name`. O(#processes).
std::vector<pid_t> childrenNamed(pid_t parent, const std::string& name)
{
  std::vector<pid_t> found;
  for (const ProcessEntry& process : runningProcesses())
    if (process.parent == parent && process.name == name)
      found.push_back(process.pid);
  return found;
}

// Without a display `mocap review` starts its own X server (Xvfb -displayfd): two at once never race
// for one display, and Ctrl+C at a terminal (SIGINT to the whole process group) stops the review
// cleanly (exit 130, no file) and ends the server with it.
TEST(ReviewExport, MocapReviewWithoutADisplayOwnsItsServerAndStopsOnCtrlC)
{
  if (std::system("command -v Xvfb setsid >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "Xvfb or setsid is not installed (Debian packages xvfb, util-linux)";
  test::TempDir dir;
  QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
  environment.remove(QStringLiteral("DISPLAY"));
  environment.remove(QStringLiteral("WAYLAND_DISPLAY"));
  const auto review = [&](QProcess& process, const std::string& name, const QString& frames) {
    process.setProcessEnvironment(environment);
    process.start(QStringLiteral("setsid"),
                  {QString::fromUtf8(checkout::cliProgram()), QStringLiteral("review"),
                   QString::fromStdString(test::sampleTake().string()), QStringLiteral("-o"),
                   QString::fromStdString(dir.file(name).string()), QStringLiteral("--size"), QStringLiteral("320x180"),
                   QStringLiteral("--frames"), frames});
  };
  QProcess first, second;
  review(first, "a.mp4", QStringLiteral("1:20"));
  review(second, "b.mp4", QStringLiteral("1:20"));
  ASSERT_TRUE(first.waitForFinished(120000));
  ASSERT_TRUE(second.waitForFinished(120000));
  EXPECT_EQ(first.exitCode(), 0) << first.readAllStandardError().toStdString();
  EXPECT_EQ(second.exitCode(), 0) << second.readAllStandardError().toStdString();
  EXPECT_TRUE(std::filesystem::exists(dir.file("a.mp4")) && std::filesystem::exists(dir.file("b.mp4")));

  QProcess stopped;
  review(stopped, "stopped.mp4", QStringLiteral("1:3000"));
  ASSERT_TRUE(stopped.waitForStarted(10000));
  const auto group = static_cast<pid_t>(stopped.processId());  // setsid: the review leads its own group
  std::vector<pid_t> server;
  for (int i = 0; i < 200 && server.empty(); ++i, QTest::qWait(50))
    server = childrenNamed(group, "Xvfb");
  ASSERT_EQ(server.size(), 1u) << "its own X server";
  QTest::qWait(2000);  // rendering by now
  ASSERT_EQ(::kill(-group, SIGINT), 0);
  ASSERT_TRUE(stopped.waitForFinished(60000));
  EXPECT_EQ(stopped.exitCode(), 130) << stopped.readAllStandardError().toStdString();
  EXPECT_FALSE(std::filesystem::exists(dir.file("stopped.mp4")));
  EXPECT_EQ(test::entryCount(dir.path()), 2u) << "no partial file beside the two videos";
  EXPECT_NE(::kill(server.front(), 0), 0) << "the X server ended with the review";
}

} // namespace
} // namespace mocap
