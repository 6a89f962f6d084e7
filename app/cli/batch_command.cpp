#include "cli_error.h"
#include "arguments.h"
#include "commands.h"
#include "stop_signal.h"

#include "mocap/base/parallel_for.h"
#include "mocap/batch/batch_runner.h"
#include "mocap/batch/clean_preset.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

namespace mocap::cli {

namespace {

struct BatchArguments
{
  std::string manifest, outDir;
  int jobs = 0;
  std::optional<std::string> preset;
  bool resume = false, json = false;
  std::optional<double> minValid;
};

std::string duration(double seconds)
{
  if (!std::isfinite(seconds) || seconds < 0)
    return "?";
  const auto s = static_cast<long long>(std::llround(seconds));
  std::ostringstream text;
  if (s >= 3600)
    text << s / 3600 << " h " << (s % 3600) / 60 << " min";
  else if (s >= 60)
    text << s / 60 << " min " << s % 60 << " s";
  else
    text << s << " s";
  return text.str();
}

/// The progress line: done/total, takes per second, ETA and failures. On a terminal it is one
/// line rewritten in place; otherwise one plain line per finished take (for logs).
class ProgressPrinter
{
public:
  ProgressPrinter() : m_terminal(::isatty(STDERR_FILENO) == 1) {}

  void operator()(const BatchProgress& p)
  {
    const std::size_t processed = p.done - p.skipped;
    const double rate = p.seconds > 0 ? static_cast<double>(processed) / p.seconds : 0.0;
    const double eta = rate > 0 ? static_cast<double>(p.total - p.done) / rate : -1.0;  // -1: unknown yet
    std::ostringstream line;
    line << "mocap batch: " << p.done << "/" << p.total << " takes";
    if (p.skipped > 0)
      line << " (" << p.skipped << " skipped)";
    line.precision(3);
    line << ", " << rate << " takes/s, ETA " << (p.done == p.total ? std::string("0 s") : duration(eta))
         << ", failures " << p.failed;
    if (p.lowQuality > 0)
      line << ", low quality " << p.lowQuality;
    if (m_terminal)
      std::cerr << '\r' << line.str() << "\033[K" << std::flush;
    else
      std::cerr << line.str() << '\n';
    m_dirty = m_terminal;
  }

  /// Ends the updating line so later messages start on their own.
  void finish()
  {
    if (m_dirty)
      std::cerr << '\n';
    m_dirty = false;
  }

private:
  bool m_terminal;
  bool m_dirty = false;
};

int runBatchCommand(const BatchArguments& arguments)
{
  BatchOptions options;
  options.outDir = arguments.outDir;
  options.jobs = arguments.jobs > 0 ? arguments.jobs : hardwareThreads();
  options.resume = arguments.resume;
  options.minValid = arguments.minValid;
  if (arguments.preset)
    options.preset = readCleanPreset(*arguments.preset);
  const TakeManifest manifest = readManifest(arguments.manifest, arguments.outDir);
  for (const std::string& warning : manifest.warnings)
    std::cerr << "mocap batch: warning: " << warning << '\n';

  options.cancel = &installStopSignals();
  auto printer = std::make_shared<ProgressPrinter>();
  options.progress = [printer](const BatchProgress& p) { (*printer)(p); };
  const BatchResult result = runBatch(manifest, options);
  printer->finish();

  for (std::size_t i = 0; i < result.takes.size(); ++i)
    if (result.takes[i].status == TakeStatus::Failed) {
      // Reader errors name the file already; write errors name the output.
      const std::string input = manifest.takes[i].input.string();
      const std::string& error = result.takes[i].error;
      std::cerr << "mocap batch: " << (error.rfind(input, 0) == 0 ? "" : input + ": ") << error << '\n';
    } else if (result.takes[i].lowQuality)
      std::cerr << "mocap batch: " << manifest.takes[i].input.string() << ": valid fraction after cleaning "
                << result.takes[i].validAfter << " is below --min-valid " << *options.minValid << '\n';
  const std::string reportPath = (options.outDir / batchReportName()).string();
  if (arguments.json) {
    std::cout << batchReportJson(manifest, options, result);
  } else {
    const std::size_t processed = result.count(TakeStatus::Cleaned) + result.count(TakeStatus::Failed);
    std::ostringstream rates;
    rates.precision(3);
    rates << (result.seconds > 0 ? static_cast<double>(processed) / result.seconds : 0.0) << " takes/s, "
          << (result.seconds > 0 ? static_cast<double>(result.inputBytes) / 1e6 / result.seconds : 0.0) << " MB/s";
    std::cout << "cleaned " << result.count(TakeStatus::Cleaned) << ", skipped " << result.count(TakeStatus::Skipped)
              << ", failed " << result.count(TakeStatus::Failed) << ", not run " << result.count(TakeStatus::NotRun)
              << ", low quality " << result.lowQualityCount() << " of " << result.takes.size() << " takes in "
              << duration(result.seconds) << " (" << rates.str() << ", " << options.jobs << " jobs)\n"
              << "report: " << reportPath << '\n';
  }
  if (result.cancelled && result.count(TakeStatus::NotRun) > 0) {
    std::cerr << "mocap batch: stopped; " << result.count(TakeStatus::NotRun)
              << " takes not run (finished takes are kept; --resume continues)\n";
    return kExitInterrupted;
  }
  if (result.count(TakeStatus::Failed) > 0)
    return kExitBadInput;
  return result.lowQualityCount() > 0 ? kExitQuality : kExitOk;
}

} // namespace

Command addBatch(CLI::App& mocap)
{
  CLI::App* command = mocap.add_subcommand(
      "batch", "clean every take of a manifest in parallel into OUTDIR, with a report per take and OUTDIR/batch.json");
  const auto a = std::make_shared<BatchArguments>();
  command
      ->add_option("MANIFEST", a->manifest,
                   "a text file, one take per line (relative to its folder; # comments), or a folder searched for "
                   ".c3d/.trc")
      ->required();
  command->add_option("-o,--output", a->outDir, "the folder the cleaned takes go to, mirroring the inputs' tree")
      ->required()
      ->type_name("OUTDIR");
  wholeNumberIn(command->add_option("--jobs", a->jobs, "takes cleaned at once; default: one per core")
                    ->type_name("N"),
                1, 4096);
  command->add_option("--preset", a->preset, "cleaning options as JSON (mocap clean's defaults without it)")
      ->type_name("PRESET.json");
  command->add_flag("--resume", a->resume, "skip takes already cleaned from the same input with the same preset");
  command->add_flag("--json", a->json, "print the batch report (OUTDIR/batch.json) instead of the summary");
  numberIn(command->add_option("--min-valid", a->minValid,
                               "quality check: exit 3 when a take's valid fraction after cleaning is below F")
               ->type_name("F"),
           0.0, 1.0);
  return {command, [a] { return runBatchCommand(*a); }};
}

} // namespace mocap::cli
