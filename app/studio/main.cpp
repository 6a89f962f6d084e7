// mocap-studio: the desktop editor. Parses the command line and wires the main window; all
// views, models and commands live in mocap::widgets.
#include "language.h"
#include "main_window.h"
#include "studio_profile.h"
#include "ui_stall_meter.h"

#include "document/autosave.h"
#include "document/studio_options.h"
#include "document/take_document.h"
#include "views/redraw_memory.h"
#include "views/vtk_viewport.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>
#include <QElapsedTimer>
#include <QStatusBar>
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
    const QImage image = mocap::ui::grabWithViewports(window);  // the 3D view included
    if (image.isNull() || !image.save(path)) {
      std::cerr << "mocap-studio: cannot write screenshot " << path.toStdString() << '\n';
      QApplication::exit(1);
      return;
    }
    QApplication::exit(0);
  });
}

} // namespace

int main(int argc, char** argv)
{
  mocap::ui::keepRedrawMemoryMapped();
  QSurfaceFormat::setDefaultFormat(mocap::ui::VtkViewport::defaultFormat());  // before QApplication
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("MocapStudio"));
  QApplication::setApplicationName(QStringLiteral("Mocap Studio"));
  QApplication::setApplicationVersion(QStringLiteral(MOCAP_VERSION));
  QString language = mocap::ui::StudioOptions().language;  // empty: the system's
  if (language.isEmpty())
    language = mocap::studio::defaultLanguage();
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
                                   QStringLiteral("Step through every frame, run Track and Label, the swap search and each cleaning preview, print frame times and UI-thread stalls as JSON, exit."));
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
  const QCommandLineOption rig(QStringLiteral("rig"),
                               QStringLiteral("Load a blendshape rig (.glb/.gltf, or a neutral .obj with --rig-shapes); "
                                              "--binding without --mesh is then the binding on its neutral."),
                               QStringLiteral("RIG"));
  const QCommandLineOption rigShapes(QStringLiteral("rig-shapes"),
                                     QStringLiteral("The folder of shape OBJs of an OBJ rig."), QStringLiteral("DIR"));
  const QCommandLineOption solve(QStringLiteral("solve"), QStringLiteral("Solve the take to the rig's weights."));
  const QCommandLineOption video(QStringLiteral("video"), QStringLiteral("Show a reference video beside the take."),
                                 QStringLiteral("VIDEO"));
  const QCommandLineOption videoOffset(QStringLiteral("video-offset"),
                                       QStringLiteral("The video's time at the take's first frame, in seconds."),
                                       QStringLiteral("S"));
  const QCommandLineOption recover(
      QStringLiteral("recover"),
      QStringLiteral("Recover the newest unsaved take a crashed studio left, with its session, without asking."));
  const QCommandLineOption autosaveSeconds(
      QStringLiteral("autosave-seconds"),
      QStringLiteral("Copy unsaved edits to the recovery file every S seconds (at least 1; default: the preferences')."),
      QStringLiteral("S"));
  parser.addOptions({screenshot, frame, select, profile, profileFrames, mesh, binding, showDock, rig, rigShapes, solve,
                     video, videoOffset, recover, autosaveSeconds});
  parser.process(app);

  mocap::studio::MainWindow window;
  if (parser.isSet(autosaveSeconds)) {
    bool ok = false;
    const double seconds = parser.value(autosaveSeconds).toDouble(&ok);
    if (!ok || !(seconds >= 1.0 && seconds <= 86400.0)) {
      std::cerr << "mocap-studio: --autosave-seconds needs a number of seconds from 1 to 86400\n";
      return 2;
    }
    window.autosave()->setInterval(static_cast<int>(seconds * 1000.0));
  }
  mocap::studio::OpenFigures open;
  if (!parser.positionalArguments().isEmpty()) {
    QElapsedTimer openClock;
    openClock.start();
    mocap::studio::UiStallMeter meter;
    meter.start();
    const QString error = window.openFile(parser.positionalArguments().front(), parser.isSet(screenshot));
    open.seconds = static_cast<double>(openClock.nsecsElapsed()) * 1e-9;
    open.stallMs = meter.stop();
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
  if (parser.isSet(rig)) {
    const QString error = window.loadRig(parser.value(rig), parser.value(rigShapes),
                                         parser.isSet(mesh) ? QString() : parser.value(binding), parser.isSet(solve));
    if (!error.isEmpty()) {
      std::cerr << "mocap-studio: " << error.toStdString() << '\n';
      if (parser.isSet(screenshot))
        return 1;
    }
  }
  if (parser.isSet(video)) {
    bool ok = true;
    std::optional<double> offset;  // unset: the offset the take remembers for the video, else 0
    if (parser.isSet(videoOffset))
      offset = parser.value(videoOffset).toDouble(&ok);
    if (!ok) {
      std::cerr << "mocap-studio: --video-offset needs a number of seconds\n";
      return 2;
    }
    const QString error = window.openReferenceVideo(parser.value(video), offset);
    if (!error.isEmpty()) {
      std::cerr << "mocap-studio: " << error.toStdString() << '\n';
      if (parser.isSet(screenshot))
        return 1;
    }
  }
  // Raised once the window is up: a hidden window's tabified docks may come up on another tab.
  const QStringList docks = parser.values(showDock);
  for (const QString& name : docks)
    if (!window.showDock(name))
      std::cerr << "mocap-studio: no dock named " << name.toStdString() << '\n';
  QTimer::singleShot(0, &window, [&window, docks] {
    for (const QString& name : docks)
      (void)window.showDock(name);
  });
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
    return mocap::studio::profileStudio(window, open,
                           limit > 0 ? static_cast<Eigen::Index>(limit) : window.document().take().frameCount());
  }
  if (parser.isSet(screenshot))
    scheduleScreenshot(window, parser.value(screenshot));
  window.show();
  if (parser.isSet(recover)) {
    if (!window.offerRecovery(false)) {
      std::cerr << "mocap-studio: no unsaved take of a crashed studio to recover\n";
      return 1;
    }
    std::cout << "mocap-studio: " << window.statusBar()->currentMessage().toStdString() << std::endl;
  } else if (!parser.isSet(screenshot)) {
    QTimer::singleShot(0, &window, [&window] { window.offerRecovery(); });
  }
  return QApplication::exec();
}
