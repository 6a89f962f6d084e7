// `mocap-review`: the program behind `mocap review`. It sets up the studio's window, hidden, with
// the take, face mesh and solved rig the arguments name (the same calls mocap-studio's command line
// makes), then writes the review video from it as File ▸ Export Review Video… does. Needs a display
// (mocap review starts it under xvfb-run when there is none). Exit codes as mocap's.
#include "arguments.h"
#include "cli_error.h"
#include "frame_range.h"
#include "main_window.h"
#include "review_arguments.h"
#include "usage.h"

#include "dialogs/review_export.h"
#include "document/take_document.h"
#include "mocap/base/json_writer.h"
#include "views/marker_view_3d.h"
#include "views/redraw_memory.h"
#include "views/vtk_viewport.h"

#include <QApplication>
#include <QFileInfo>
#include <QSurfaceFormat>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace {

using namespace mocap;
using namespace mocap::cli;

/// Builds the studio's state the arguments describe; returns "" or the error.
QString setUp(studio::MainWindow& window, const ReviewArguments& a)
{
  QString error = window.openFile(QString::fromStdString(a.take), true);
  if (error.isEmpty() && a.mesh)
    error = window.loadFaceMesh(QString::fromStdString(*a.mesh), QString::fromStdString(a.binding.value_or("")));
  if (error.isEmpty() && a.solve)
    error = window.loadRig(QString::fromStdString(*a.solve), QString::fromStdString(a.rigShapes.value_or("")),
                           a.mesh ? QString() : QString::fromStdString(a.binding.value_or("")), true);
  if (!error.isEmpty())
    return error;
  window.markerView()->setTrailFrames(a.trails);
  if (a.select) {
    const QStringList labels = QString::fromStdString(*a.select).split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (window.selectLabels(labels) != labels.size())
      return QStringLiteral("--select: not every label is a marker of the take");
  }
  return {};
}

/// Progress on stderr: one updating line on a terminal, a line per tenth otherwise.
bool reportProgress(long long done, long long total)
{
  QCoreApplication::processEvents();
  static const bool terminal = ::isatty(STDERR_FILENO) != 0;
  if (terminal)
    std::fprintf(stderr, "\rmocap review: frame %lld of %lld", done, total);
  else if (done == total || done % std::max(1LL, total / 10) == 0)
    std::fprintf(stderr, "mocap review: %lld of %lld frames\n", done, total);
  if (terminal && done == total)
    std::fputc('\n', stderr);
  return true;
}

void printOutcome(const ui::ReviewOutcome& outcome, const ui::ReviewRequest& request, double rate, bool json)
{
  const double perSecond = outcome.seconds > 0.0 ? static_cast<double>(outcome.frames) / outcome.seconds : 0.0;
  if (!json) {
    std::cout << "wrote " << outcome.encoding.path.string() << ": " << outcome.frames << " frames, "
              << request.size.width() << " x " << request.size.height() << ", " << rate << " fps, "
              << outcome.encoding.codec << " in " << outcome.encoding.container << " ("
              << fixedNumber(perSecond, 1) << " frames/s)\n";
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
  out.endObject();
  std::cout << out.str() << '\n';
}

int review(const ReviewArguments& a)
{
  const auto [width, height] = parseReviewSize(a.size);
  studio::MainWindow window;
  if (const QString error = setUp(window, a); !error.isEmpty()) {
    std::cerr << "mocap review: " << error.toStdString() << '\n';
    return kExitBadInput;
  }
  const Take& take = window.document().take();
  const auto [begin, end] = parseFrameRange(a.frames, take);
  ui::ReviewRequest request;
  request.output = a.output;
  request.size = QSize(width, height);
  request.first = begin;
  request.last = end - 1;
  request.video = QString::fromStdString(a.video.value_or(""));
  request.videoOffset = a.offset;
  request.takeName = QFileInfo(QString::fromStdString(a.take)).completeBaseName().toStdString();
  ui::ReviewSource source = window.reviewSource();
  source.resetCamera = true;
  const ui::ReviewOutcome outcome = ui::exportReview(source, request, reportProgress);
  if (!outcome.done) {
    std::cerr << "mocap review: " << outcome.error.toStdString() << '\n';
    return kExitBadInput;
  }
  if (outcome.encoding.path != request.output)
    std::cerr << "mocap review: no MP4 encoder here; wrote Motion JPEG AVI instead\n";
  printOutcome(outcome, request, take.frameRate(), a.json);
  return kExitOk;
}

} // namespace

int main(int argc, char** argv)
{
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
  ui::keepRedrawMemoryMapped();
  QSurfaceFormat::setDefaultFormat(ui::VtkViewport::defaultFormat());  // before QApplication
  QApplication application(argc, argv);
  // Settings of their own: a review looks the same whatever the studio last remembered.
  QApplication::setOrganizationName(QStringLiteral("MocapStudio"));
  QApplication::setApplicationName(QStringLiteral("Mocap Review"));
  try {
    return review(arguments);
  } catch (const UsageError& e) {
    std::cerr << "mocap review: " << e.what() << '\n' << usageHint(command) << '\n';
    return kExitBadUsage;
  } catch (const std::exception& e) {
    std::cerr << "mocap review: " << e.what() << '\n';
    return kExitBadInput;
  }
}
