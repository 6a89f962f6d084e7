// `mocap-review`: the program behind `mocap review`. It loads a studio session from the files the
// arguments name (the take, face mesh, binding and blendshape rig, solved to the take) with no
// widget at all, then writes the review video from it as File ▸ Export Review Video… does: the
// same scene, framed on the reviewed frames, rendered in VTK's off-screen window. Needs an X
// display for that window's GL context (mocap review starts it under xvfb-run when there is none).
// Exit codes as mocap's.
#include "arguments.h"
#include "cli_error.h"
#include "frame_range.h"
#include "review_arguments.h"
#include "stop_signal.h"
#include "usage.h"

#include "dialogs/review_export.h"
#include "document/session_files.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "mocap/base/json_writer.h"
#include "views/redraw_memory.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QGuiApplication>
#include <QStringList>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <utility>
#include <unistd.h>

namespace {

using namespace mocap;
using namespace mocap::cli;

/// The session the arguments describe, loaded from the files they name, with the selection.
/// Returns "" or the error.
QString setUp(ui::StudioSession& session, const ReviewArguments& a)
{
  ui::SessionFiles files;
  files.take = QString::fromStdString(a.take);
  files.mesh = QString::fromStdString(a.mesh.value_or(""));
  files.rig = QString::fromStdString(a.solve.value_or(""));
  files.rigShapes = QString::fromStdString(a.rigShapes.value_or(""));
  files.binding = QString::fromStdString(a.binding.value_or(""));
  files.solve = a.solve.has_value();
  if (const QString error = ui::loadSessionFiles(session, files); !error.isEmpty())
    return error;
  if (a.select) {
    const QStringList labels = QString::fromStdString(*a.select).split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (session.document().selectLabels(labels) != labels.size())
      return QStringLiteral("--select: not every label is a marker of the take");
  }
  return {};
}

/// Progress on stderr: one updating line on a terminal, a line per tenth otherwise (which
/// mocap.write_review_video reads). False once SIGINT or SIGTERM came: the export then stops at
/// this frame and removes its partial video.
bool reportProgress(long long done, long long total, const std::atomic<bool>& stop)
{
  QCoreApplication::processEvents();
  static const bool terminal = ::isatty(STDERR_FILENO) != 0;
  if (terminal)
    std::fprintf(stderr, "\rmocap review: frame %lld of %lld", done, total);
  else if (done == total || done % std::max(1LL, total / 10) == 0)
    std::fprintf(stderr, "mocap review: %lld of %lld frames\n", done, total);
  if (terminal && done == total)
    std::fputc('\n', stderr);
  return !stop.load();
}

void printOutcome(const ui::ReviewOutcome& outcome, const ui::ReviewRequest& request, double rate, bool json,
                  double firstFrameSeconds)
{
  const double perSecond = outcome.seconds > 0.0 ? static_cast<double>(outcome.frames) / outcome.seconds : 0.0;
  if (!json) {
    std::cout << "wrote " << outcome.encoding.path.string() << ": " << outcome.frames << " frames, "
              << request.size.width() << " x " << request.size.height() << ", " << rate << " fps, "
              << outcome.encoding.codec << " in " << outcome.encoding.container << " ("
              << fixedNumber(perSecond, 1) << " frames/s, first frame after " << fixedNumber(firstFrameSeconds, 2)
              << " s)\n";
    return;
  }
  JsonWriter out;
  out.beginObject();
  out.key("output").value(outcome.encoding.path.string());
  out.key("codec").value(outcome.encoding.codec);
  out.key("container").value(outcome.encoding.container);
  out.key("frames").value(static_cast<std::int64_t>(outcome.frames));
  out.key("width").value(request.size.width());
  out.key("height").value(request.size.height());
  out.key("frame_rate").value(rate);
  out.key("reference_video").value(request.video.toStdString());
  out.key("seconds").value(outcome.seconds);
  out.key("frames_per_second").value(perSecond);
  out.key("first_frame_seconds").value(firstFrameSeconds);
  out.endObject();
  std::cout << out.str() << '\n';
}

/// `clock` runs since the program started: the time to the first frame is read on it. `stop` is
/// set by SIGINT or SIGTERM: the export then stops at its next frame (one that came while the
/// session loaded stops it at the first).
int review(const ReviewArguments& a, const QElapsedTimer& clock, const std::atomic<bool>& stop)
{
  const auto [width, height] = parseReviewSize(a.size);
  ui::StudioSession session;
  if (const QString error = setUp(session, a); !error.isEmpty()) {
    std::cerr << "mocap review: " << error.toStdString() << '\n';
    return kExitBadInput;
  }
  const Take& take = session.document().take();
  const auto [begin, end] = parseFrameRange(a.frames, take);
  ui::ReviewRequest request;
  request.output = a.output;
  request.size = QSize(width, height);
  request.first = begin;
  request.last = end - 1;
  request.video = QString::fromStdString(a.video.value_or(""));
  request.videoOffset = a.offset;
  request.takeName = QFileInfo(QString::fromStdString(a.take)).completeBaseName().toStdString();
  ui::ReviewSource source;
  source.session = &session;
  source.settings.trailFrames = a.trails;
  source.resetCamera = true;  // framed on the reviewed frames
  double firstFrameSeconds = 0.0;
  const ui::ReviewOutcome outcome = ui::exportReview(source, request, [&](long long done, long long total) {
    if (done == 1)
      firstFrameSeconds = static_cast<double>(clock.nsecsElapsed()) * 1e-9;
    return reportProgress(done, total, stop);
  });
  if (outcome.cancelled) {
    std::cerr << "\nmocap review: interrupted; no video written\n";
    return kExitInterrupted;
  }
  if (!outcome.done) {
    std::cerr << "mocap review: " << outcome.error.toStdString() << '\n';
    return kExitBadInput;
  }
  if (outcome.encoding.path != request.output)
    std::cerr << "mocap review: no MP4 encoder here; wrote Motion JPEG AVI instead\n";
  printOutcome(outcome, request, take.frameRate(), a.json, firstFrameSeconds);
  return kExitOk;
}

} // namespace

int main(int argc, char** argv)
{
  QElapsedTimer clock;
  clock.start();
  const std::atomic<bool>& stop = installStopSignals();
  // Parsed as `mocap review`, so the usage and errors read as mocap's own.
  CLI::App mocap("the batch command line of Mocap Studio", "mocap");
  mocap.formatter(std::make_shared<UsageFormatter>());
  mocap.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  CLI::App& command = *mocap.add_subcommand("review", "renders a review video of a take");
  ReviewArguments arguments;
  defineReviewOptions(command, arguments);
  std::vector<std::string> args(argv + 1, argv + argc);
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last first
  args.emplace_back("review");
  try {
    mocap.parse(args);
  } catch (const CLI::CallForHelp&) {
    std::cout << command.help();
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    std::cerr << "mocap review: " << e.what() << '\n' << usageHint(command) << '\n';
    return kExitBadUsage;
  }
  ui::keepRedrawMemoryMapped();  // each frame's pixels are a few MB read back and freed
  // Qt shows nothing here, so it needs no display (VTK's off-screen window opens its own, and says
  // so when there is none); the session's models want a GUI application all the same.
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", "offscreen");
  QGuiApplication application(argc, argv);
  try {
    return review(arguments, clock, stop);
  } catch (const UsageError& e) {
    std::cerr << "mocap review: " << e.what() << '\n' << usageHint(command) << '\n';
    return kExitBadUsage;
  } catch (const std::exception& e) {
    std::cerr << "mocap review: " << e.what() << '\n';
    return kExitBadInput;
  }
}
