// mocap-studio: the desktop editor. Parses the command line and wires the main window; all
// views, models and commands live in mocap::widgets.
#include "language.h"
#include "main_window.h"

#include "document/take_document.h"
#include "panels/face_mesh_panel.h"
#include "views/face_mesh_scene.h"
#include "views/marker_view_3d.h"
#include "views/vtk_viewport.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSettings>
#include <QSurfaceFormat>
#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>
#include <vector>

#include <iostream>

namespace {

/// Renders the window at 1280×800 once the view has painted, writes `path` and quits.
void scheduleScreenshot(mocap::studio::MainWindow& window, const QString& path)
{
  window.resize(1280, 800);
  QTimer::singleShot(1500, &window, [&window, path] {
    const QImage image = window.grab().toImage();
    if (image.isNull() || !image.save(path)) {
      std::cerr << "mocap-studio: cannot write screenshot " << path.toStdString() << '\n';
      QApplication::exit(1);
      return;
    }
    QApplication::exit(0);
  });
}

/// Steps through every frame with the selection's trails drawn, painting what changed, and
/// prints frame-time statistics as JSON (the playback budget at 100 Hz is 10 ms), with the time
/// the file took to open (read, table statistics, views).
int profilePlayback(mocap::studio::MainWindow& window, double openSeconds, Eigen::Index maxFrames)
{
  window.resize(1280, 800);
  window.show();
  QApplication::processEvents();
  auto& document = window.document();
  const Eigen::Index frames = std::min(document.take().frameCount(), maxFrames);
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(frames));
  const mocap::ui::FaceMeshScene& mesh = window.faceMeshPanel()->scene();
  double deformSum = 0.0;
  Eigen::Index deformCount = 0;
  QElapsedTimer total;
  total.start();
  for (Eigen::Index f = 0; f < frames; ++f) {
    QElapsedTimer clock;
    clock.start();
    document.setCurrentFrame(f);
    // What playback does: the views that changed ask for an update, and the event loop paints
    // them (the 3D render included) before the next frame.
    QApplication::processEvents();
    times.push_back(static_cast<double>(clock.nsecsElapsed()) * 1e-6);
    if (mesh.lastDeformMs() >= 0.0) {
      deformSum += mesh.lastDeformMs();
      ++deformCount;
    }
  }
  const double seconds = static_cast<double>(total.nsecsElapsed()) * 1e-9;
  std::vector<double> sorted = times;
  std::sort(sorted.begin(), sorted.end());
  auto percentile = [&](double p) {
    return sorted.empty() ? 0.0 : sorted[static_cast<std::size_t>(p * static_cast<double>(sorted.size() - 1))];
  };
  double mean = 0.0;
  for (double t : times)
    mean += t;
  mean /= std::max<double>(static_cast<double>(times.size()), 1.0);
  std::cout << "{\"open_seconds\": " << openSeconds << ", \"frames\": " << frames << ", \"seconds\": " << seconds << ", \"mean_ms\": " << mean
            << ", \"median_ms\": " << percentile(0.5) << ", \"p95_ms\": " << percentile(0.95)
            << ", \"max_ms\": " << (sorted.empty() ? 0.0 : sorted.back())
            << ", \"take_rate_hz\": " << document.take().frameRate();
  // Autosave's share of the UI thread: the copy of the take handed to its worker.
  QElapsedTimer copyClock;
  copyClock.start();
  const mocap::Take copy = document.take();
  std::cout << ", \"autosave_ui_copy_ms\": " << static_cast<double>(copyClock.nsecsElapsed()) * 1e-6
            << ", \"autosave_copy_frames\": " << copy.frameCount();
  if (deformCount > 0)  // with --mesh: the face rig's deform alone, per frame
    std::cout << ", \"mesh_deform_ms_mean\": " << deformSum / static_cast<double>(deformCount);
  std::cout << "}\n";
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  QSurfaceFormat::setDefaultFormat(mocap::ui::VtkViewport::defaultFormat());  // before QApplication
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("MocapStudio"));
  QApplication::setApplicationName(QStringLiteral("Mocap Studio"));
  QApplication::setApplicationVersion(QStringLiteral(MOCAP_VERSION));
  const QString language =
      QSettings().value(QStringLiteral("language"), mocap::studio::defaultLanguage()).toString();
  if (!mocap::studio::installLanguage(app, language))
    mocap::studio::installLanguage(app, QStringLiteral("en"));

  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral("Mocap Studio: clean and use facial motion capture."));
  parser.addHelpOption();
  parser.addPositionalArgument(QStringLiteral("file"), QStringLiteral("A take to open (.c3d, .trc)."));
  const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                      QStringLiteral("Render the window at 1280x800 to OUT.png and exit."),
                                      QStringLiteral("OUT.png"));
  const QCommandLineOption frame(QStringLiteral("frame"), QStringLiteral("Show frame N (file numbering)."),
                                 QStringLiteral("N"));
  const QCommandLineOption select(QStringLiteral("select"), QStringLiteral("Select markers LABEL,..."),
                                  QStringLiteral("LABELS"));
  const QCommandLineOption profile(QStringLiteral("profile"),
                                   QStringLiteral("Step through every frame, print frame times as JSON, exit."));
  const QCommandLineOption profileFrames(QStringLiteral("profile-frames"),
                                         QStringLiteral("With --profile, step through only the first N frames."),
                                         QStringLiteral("N"));
  const QCommandLineOption mesh(QStringLiteral("mesh"), QStringLiteral("Drive a face mesh (.obj, .ply) with the take."),
                                QStringLiteral("FILE"));
  const QCommandLineOption binding(QStringLiteral("binding"),
                                   QStringLiteral("With --mesh, the marker binding (.json) to use."),
                                   QStringLiteral("FILE"));
  const QCommandLineOption showDock(QStringLiteral("show-dock"),
                                    QStringLiteral("Show and raise the dock NAME (title or object name, e.g. Gaps)."),
                                    QStringLiteral("NAME"));
  parser.addOptions({screenshot, frame, select, profile, profileFrames, mesh, binding, showDock});
  parser.process(app);

  mocap::studio::MainWindow window;
  double openSeconds = 0.0;
  if (!parser.positionalArguments().isEmpty()) {
    QElapsedTimer openClock;
    openClock.start();
    const QString error = window.openFile(parser.positionalArguments().front(), parser.isSet(screenshot));
    openSeconds = static_cast<double>(openClock.nsecsElapsed()) * 1e-9;
    if (!error.isEmpty() && parser.isSet(screenshot)) {
      std::cerr << error.toStdString() << '\n';
      return 1;
    }
  }
  if (parser.isSet(mesh)) {
    const QString error = window.loadFaceMesh(parser.value(mesh), parser.value(binding));
    if (!error.isEmpty()) {
      std::cerr << "mocap-studio: " << error.toStdString() << '\n';
      if (parser.isSet(screenshot))
        return 1;
    }
  }
  for (const QString& name : parser.values(showDock))
    if (!window.showDock(name))
      std::cerr << "mocap-studio: no dock named " << name.toStdString() << '\n';
  if (parser.isSet(select))
    window.selectLabels(parser.value(select).split(QLatin1Char(','), Qt::SkipEmptyParts));
  if (parser.isSet(frame)) {
    bool ok = false;
    const qlonglong number = parser.value(frame).toLongLong(&ok);
    if (!ok) {
      std::cerr << "mocap-studio: --frame needs a frame number\n";
      return 2;
    }
    window.document().setCurrentFrame(static_cast<Eigen::Index>(number - window.document().take().firstFrame()));
  }
  if (parser.isSet(profile)) {
    bool ok = true;
    const qlonglong limit = parser.isSet(profileFrames) ? parser.value(profileFrames).toLongLong(&ok) : -1;
    if (!ok || (parser.isSet(profileFrames) && limit < 1)) {
      std::cerr << "mocap-studio: --profile-frames needs a positive number of frames\n";
      return 2;
    }
    return profilePlayback(window, openSeconds,
                           limit > 0 ? static_cast<Eigen::Index>(limit) : window.document().take().frameCount());
  }
  if (parser.isSet(screenshot))
    scheduleScreenshot(window, parser.value(screenshot));
  window.show();
  if (!parser.isSet(screenshot))
    QTimer::singleShot(0, &window, [&window] { window.offerRecovery(); });
  return QApplication::exec();
}
