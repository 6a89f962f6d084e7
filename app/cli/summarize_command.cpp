#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/batch/archive_summary.h"

#include <iostream>
#include <memory>

namespace mocap::cli {

namespace {

struct SummarizeArguments
{
  std::string outDir;
  std::optional<std::string> html;
  bool json = false;
  double minValid = 0.9;
};

int runSummarize(const SummarizeArguments& arguments)
{
  if (!arguments.html && !arguments.json)
    throw UsageError("nothing to write: give -o REPORT.html, --json or both");
  const ArchiveSummary summary = summarizeArchive(arguments.outDir, arguments.minValid);
  if (summary.reports.empty())
    throw IoError(arguments.outDir + ": no take report (*.report.json) here; run mocap batch first");
  for (const std::string& problem : summary.unreadable)
    std::cerr << "mocap summarize: warning: " << problem << '\n';
  if (arguments.html)
    writeFileAtomically(*arguments.html, archiveSummaryHtml(summary));
  if (arguments.json)
    std::cout << archiveSummaryJson(summary);
  else
    std::cout << summary.reports.size() << " takes, " << summary.review.size() << " to review; report: "
              << *arguments.html << '\n';
  return kExitOk;
}

} // namespace

Command addSummarize(CLI::App& mocap)
{
  CLI::App* command =
      mocap.add_subcommand("summarize", "one self-contained HTML page of a batch's per-take reports");
  const auto a = std::make_shared<SummarizeArguments>();
  command->add_option("OUTDIR", a->outDir, "the OUTDIR of mocap batch")->required();
  command->add_option("-o,--output", a->html, "the HTML report (inline SVG plots, no network)")
      ->type_name("REPORT.html");
  command->add_flag("--json", a->json, "print the figures as JSON");
  numberIn(command->add_option("--min-valid", a->minValid,
                               "takes below this valid fraction after cleaning need a person")
               ->type_name("F"),
           0.0, 1.0)
      ->capture_default_str();
  return {command, [a] { return runSummarize(*a); }};
}

} // namespace mocap::cli
