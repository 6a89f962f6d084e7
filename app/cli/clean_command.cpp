#include "take_input.h"
#include "take_output.h"
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/batch/batch_runner.h"
#include "mocap/batch/clean_preset.h"
#include "mocap/batch/clean_run.h"
#include "mocap/cleaning/clean_pipeline.h"
#include "mocap/cleaning/smoothing.h"
#include "mocap/cleaning/spike_detection.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_writer.h"
#include "mocap/io/take_io.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/provenance.h"

#include <cstdlib>
#include <iostream>
#include <memory>

namespace mocap::cli {

namespace {

/// The options of `mocap clean`; the core's option structs hold the defaults the usage shows.
struct CleanArguments
{
  std::string input, output;
  std::string spikes = std::string(spikeMethodName(SpikeOptions{}.method));
  SpikeOptions spikeOptions;
  std::string fill = std::string(fillMethodName(FillOptions{}.method));
  FillOptions fillOptions;
  std::optional<Eigen::Index> maxGap;
  std::optional<double> maxGapSeconds;
  std::string smooth = std::string(smoothMethodName(SmoothOptions{}.method));
  SmoothOptions smoothOptions;
  std::optional<std::string> stabilize;  ///< "" (bare --stabilize): the head markers saved in IN
  bool keepStabilized = false;
  std::optional<std::string> report;
  std::optional<std::string> preset, manifest;
  std::optional<long long> index;
  bool resume = false;
  bool count = false;
  std::optional<double> minValidAfter;  ///< quality check: exit 3 below this valid fraction after cleaning
};

/// Exit 3 (the batch's quality exit) when the cleaned take's valid fraction is below --min-valid-after.
int qualityExit(const CleanArguments& arguments, const std::string& input, double validAfter)
{
  if (!arguments.minValidAfter || validAfter >= *arguments.minValidAfter)
    return kExitOk;
  std::cerr << "mocap clean: " << input << ": valid fraction after cleaning " << validAfter
            << " is below --min-valid-after " << *arguments.minValidAfter << '\n';
  return kExitQuality;
}

std::optional<SpikeOptions> spikeOptions(const CleanArguments& arguments)
{
  if (arguments.spikes == "off")
    return std::nullopt;
  SpikeOptions options = arguments.spikeOptions;
  options.method = parseSpikeMethod(arguments.spikes).value();
  return options;
}

std::optional<FillOptions> fillOptions(const CleanArguments& arguments)
{
  if (arguments.fill == "off")
    return std::nullopt;
  FillOptions options = arguments.fillOptions;
  options.method = parseFillMethod(arguments.fill).value();
  if (arguments.maxGap) {
    options.maxGap = *arguments.maxGap;
    if (*arguments.maxGap == 0)
      options.maxGapSeconds = 0.0;  // --max-gap 0: unlimited, as before
  }
  if (arguments.maxGapSeconds)
    options.maxGapSeconds = *arguments.maxGapSeconds;
  return options;
}

std::optional<SmoothOptions> smoothOptions(const CleanArguments& arguments)
{
  if (arguments.smooth == "off")
    return std::nullopt;
  SmoothOptions options = arguments.smoothOptions;
  options.method = parseSmoothMethod(arguments.smooth).value();
  return options;
}

std::string cleanReportJson(const std::string& input, const std::string& output, const Take& take,
                            const CleanOptions& options, const CleanReport& report)
{
  JsonWriter json;
  json.beginObject();
  json.key("input").value(input);
  json.key("output").value(output);
  json.key("stabilize").beginObject();
  json.key("markers").beginArray();
  for (Eigen::Index m : report.stabilizeMarkers)
    json.value(take.label(m));
  json.endArray();
  json.key("unknown_head_poses").value(static_cast<std::int64_t>(report.unknownHeadPoses));
  json.key("kept_stabilized").value(options.keepStabilized);
  json.endObject();
  json.key("spikes").beginObject();
  json.key("method").value(options.spikes ? spikeMethodName(options.spikes->method) : "off");
  json.key("count").value(static_cast<std::int64_t>(report.spikes.size()));
  json.key("repaired_samples").value(static_cast<std::int64_t>(report.repairedSamples));
  json.key("flagged").beginArray();
  for (const SpikeFlag& flag : report.spikes)
    json.beginObject()
        .key("marker")
        .value(take.label(flag.marker))
        .key("frame")
        .value(take.firstFrame() + flag.frame)
        .endObject();
  json.endArray();
  json.endObject();
  json.key("fill").beginObject();
  json.key("method").value(options.fill ? fillMethodName(options.fill->method) : "off");
  if (options.fill) {
    // The options used, so a report says what was left alone on purpose.
    json.key("options").beginObject();
    const FillOptions& fill = *options.fill;
    const Eigen::Index longest = longestGapFrames(fill, take.frameRate());
    json.key("max_gap_frames").value(static_cast<std::int64_t>(longest));  // 0: unlimited
    json.key("max_gap_seconds").value(static_cast<double>(longest) / take.frameRate());
    json.key("unlimited").value(longest == 0);
    json.key("extrapolate").value(fill.extrapolate);
    json.key("min_valid_fraction").value(fill.minValidFraction);
    json.key("neighbours").value(static_cast<std::int64_t>(fill.neighbours));
    json.endObject();
  }
  std::int64_t filledGaps = 0;
  for (const GapFillReport& gap : report.gaps)
    filledGaps += gap.filled ? 1 : 0;
  json.key("filled_gaps").value(filledGaps);
  json.key("unfilled_gaps").value(static_cast<std::int64_t>(report.gaps.size()) - filledGaps);
  json.key("filled_samples").value(static_cast<std::int64_t>(report.filledSamples));
  json.key("gaps").beginArray();
  for (const GapFillReport& gap : report.gaps) {
    json.beginObject();
    json.key("marker").value(take.label(gap.gap.marker));
    json.key("first_frame").value(take.firstFrame() + gap.gap.firstFrame);
    json.key("length").value(static_cast<std::int64_t>(gap.gap.length));
    json.key("filled").value(gap.filled);
    json.key("method").value(gap.method);
    if (!gap.filled) {
      json.key("reason").value(gap.reason);
      json.key("cause").value(unfilledCauseName(gap.cause));
    }
    json.endObject();
  }
  json.endArray();
  json.key("unfilled").beginArray();  // the gaps left open, with why: nothing hidden
  for (const GapFillReport& gap : report.gaps) {
    if (gap.filled)
      continue;
    json.beginObject();
    json.key("marker").value(take.label(gap.gap.marker));
    json.key("first_frame").value(take.firstFrame() + gap.gap.firstFrame);
    json.key("length").value(static_cast<std::int64_t>(gap.gap.length));
    json.key("cause").value(unfilledCauseName(gap.cause));
    json.key("reason").value(gap.reason);
    json.endObject();
  }
  json.endArray();
  json.endObject();
  json.key("smooth").beginObject();
  json.key("method").value(options.smooth ? smoothMethodName(options.smooth->method) : "off");
  json.key("smoothed_samples").value(static_cast<std::int64_t>(report.smoothedSamples));
  json.endObject();
  json.key("valid_fraction").value(markerValidFraction(take));
  json.key("model_outputs").beginObject();  // points no step touched (angles, forces...)
  json.key("untouched").value(static_cast<std::int64_t>(report.modelOutputs.size()));
  json.key("labels").beginArray();
  for (const Eigen::Index m : report.modelOutputs)
    json.value(take.label(m));
  json.endArray();
  json.endObject();
  json.endObject();
  return json.str() + "\n";
}

/// The options of the command line, or of --preset when given.
CleanOptions cleanOptions(const CleanArguments& arguments)
{
  if (arguments.preset)
    return readCleanPreset(*arguments.preset);
  CleanOptions options;
  options.spikes = spikeOptions(arguments);
  options.fill = fillOptions(arguments);
  options.smooth = smoothOptions(arguments);
  if (arguments.stabilize && !arguments.stabilize->empty())
    options.stabilizeLabels = splitList(*arguments.stabilize, "--stabilize");
  options.keepStabilized = arguments.keepStabilized;
  return options;
}

/// The manifest line to run: --index, else the array index the cluster's scheduler sets.
std::size_t manifestIndex(const CleanArguments& arguments, std::size_t count)
{
  std::optional<long long> index = arguments.index;
  std::string from = "--index";
  for (const char* variable : {"SLURM_ARRAY_TASK_ID", "JOB_COMPLETION_INDEX"}) {
    const char* value = std::getenv(variable);
    if (index || value == nullptr || *value == '\0')
      continue;
    char* end = nullptr;
    const long long parsed = std::strtoll(value, &end, 10);
    if (*end != '\0')
      throw UsageError(std::string(variable) + "='" + value + "' is not a whole number");
    index = parsed;
    from = variable;
  }
  if (!index)
    throw UsageError("--manifest needs --index I (or SLURM_ARRAY_TASK_ID / JOB_COMPLETION_INDEX set)");
  if (*index < 0 || static_cast<std::size_t>(*index) >= count)
    throw UsageError(from + " " + std::to_string(*index) + ": the manifest has " + std::to_string(count) +
                     " takes (0.." + std::to_string(count - 1) + ")");
  return static_cast<std::size_t>(*index);
}

/// `mocap clean --manifest F --index I -o OUTDIR`: take I as `mocap batch` would clean it.
int runManifestTake(const CleanArguments& arguments, const CleanOptions& options)
{
  if (arguments.report)
    throw UsageError("--report: with --manifest the report goes beside the take (OUTDIR/...report.json)");
  const TakeManifest manifest = readManifest(*arguments.manifest, arguments.output);
  const std::size_t index = manifestIndex(arguments, manifest.takes.size());
  BatchOptions batch;
  batch.outDir = arguments.output;
  batch.preset = options;
  batch.resume = arguments.resume;
  batch.minValid = arguments.minValidAfter;
  prepareOutDir(manifest, batch.outDir);
  const BatchTakeResult result = runBatchTake(manifest, index, batch);
  const ManifestEntry& entry = manifest.takes[index];
  const TakeOutputs outputs = takeOutputs(entry, batch.outDir);
  if (result.status == TakeStatus::Failed) {
    std::cerr << "mocap clean: " << entry.input.string() << ": " << result.error << '\n';
    return kExitBadInput;
  }
  std::cout << takeStatusName(result.status) << ' ' << entry.input.string() << " -> " << outputs.take.string()
            << '\n';
  return qualityExit(arguments, entry.input.string(), result.validAfter);
}

/// `mocap clean --manifest F --count`: the number of takes, for a job array's size.
int printManifestCount(const CleanArguments& arguments)
{
  const TakeManifest manifest = readManifest(*arguments.manifest, {});
  for (const std::string& warning : manifest.warnings)
    std::cerr << "mocap clean: warning: " << warning << '\n';
  std::cout << manifest.takes.size() << '\n';
  return kExitOk;
}

/// Bare --stabilize: the head markers saved in the take (headMarkers in provenance.h, which the studio
/// writes). Nothing is guessed: a take without them is refused, naming the flag.
std::vector<std::string> savedHeadMarkers(const Take& take, const std::string& input)
{
  std::vector<std::string> labels = headMarkers(take);
  if (labels.empty())
    throw UsageError(input + " has no head markers saved with it; name them: --stabilize LABEL,LABEL,LABEL "
                             "(the studio saves the ones chosen in Marker > Reference Markers...)");
  return labels;
}

int runClean(const CleanArguments& arguments)
{
  if (arguments.count)
    return printManifestCount(arguments);
  if (arguments.output.empty())
    throw UsageError("-o OUT is required (with --manifest: -o OUTDIR)");
  CleanOptions options = cleanOptions(arguments);
  const bool savedStabilize = arguments.stabilize && arguments.stabilize->empty();
  if (arguments.manifest && savedStabilize)
    throw UsageError("--stabilize without labels uses the head markers saved in IN; with --manifest name them");
  if (arguments.manifest)
    return runManifestTake(arguments, options);
  if (arguments.resume)
    throw UsageError("--resume needs --manifest");
  if (arguments.input.empty())
    throw UsageError("the take to clean is missing: give IN or --manifest F");
  const std::string& input = arguments.input;
  const std::string& output = arguments.output;
  (void)formatFromPath(output);  // reject an unknown output type before the read

  Take take = readInputTake(input);
  if (savedStabilize)
    options.stabilizeLabels = savedHeadMarkers(take, input);
  const CleanReport report = cleanAndRecord(take, options, "mocap clean");
  if (const std::string outputs = describeModelOutputs(take); !outputs.empty())
    std::cerr << "mocap clean: " << input << ": " << outputs << " left untouched\n";
  writeCleanedTake(take, report, options, output);
  noteLeftOut(take, output);
  if (arguments.report)
    writeFileAtomically(*arguments.report, cleanReportJson(input, output, take, options, report));
  return qualityExit(arguments, input, markerValidFraction(take));
}

std::vector<std::string> fillChoices()
{
  std::vector<std::string> names;
  for (const FillMethod method : allFillMethods())
    names.emplace_back(fillMethodName(method));
  names.emplace_back("off");
  return names;
}

} // namespace

Command addClean(CLI::App& mocap)
{
  CLI::App* command =
      mocap.add_subcommand("clean", "stabilize, remove spikes, fill gaps, smooth; write OUT and a JSON report");
  const auto a = std::make_shared<CleanArguments>();
  CLI::Option* input = command->add_option("IN", a->input, "the take to clean");
  command
      ->add_option("-o,--output", a->output,
                   "the cleaned take, its extension naming the format; with --manifest the OUTDIR of mocap batch "
                   "(required unless --count)")
      ->type_name("OUT");
  oneOf(command->add_option("--spikes", a->spikes, "spike detector"), spikeMethodNames() + "|off")
      ->capture_default_str();
  numberIn(command->add_option("--spike-factor", a->spikeOptions.factor, "spike detection factor")->type_name("F"),
           1e-6, 1e6)
      ->capture_default_str();
  numberIn(command->add_option("--spike-threshold", a->spikeOptions.threshold, "spike detection threshold")
               ->type_name("T"),
           1e-6, 1e6)
      ->capture_default_str();
  const std::vector<std::string> fills = fillChoices();
  std::string fillList;
  for (const std::string& name : fills)
    fillList += (fillList.empty() ? "" : ", ") + name;
  oneOf(command->add_option("--fill", a->fill, "gap-fill method: " + fillList), fills)
      ->type_name("METHOD|off")
      ->capture_default_str();
  CLI::Option* maxGapSeconds =
      numberIn(command->add_option("--max-gap-seconds", a->maxGapSeconds, "longest gap filled, in seconds")
                   ->type_name("S"),
               0.0, 1e9)
          ->default_str(numberText(FillOptions{}.maxGapSeconds));
  wholeNumberIn(command->add_option("--max-gap", a->maxGap, "longest gap filled, in frames; 0: unlimited")
                    ->type_name("N")
                    ->excludes(maxGapSeconds),
                0, 1LL << 40);
  command->add_flag("--extrapolate", a->fillOptions.extrapolate, "also fill gaps at the start and end");
  numberIn(command->add_option("--min-valid", a->fillOptions.minValidFraction,
                               "fill only markers valid in at least this fraction of the take")
               ->type_name("F"),
           0.0, 1.0)
      ->capture_default_str();
  wholeNumberIn(command->add_option("--neighbours", a->fillOptions.neighbours, "neighbour markers a fill may use")
                    ->type_name("N"),
                1, 1000)
      ->capture_default_str();
  oneOf(command->add_option("--smooth", a->smooth, "smoothing method"), smoothMethodNames() + "|off")
      ->capture_default_str();
  wholeNumberIn(command->add_option("--order", a->smoothOptions.degree, "B-spline order")->type_name("K"), 2, 7)
      ->capture_default_str();
  numberIn(command->add_option("--knot-spacing", a->smoothOptions.knotSpacing, "B-spline knot spacing, in frames")
               ->type_name("N"),
           1.0, 1e6)
      ->capture_default_str();
  numberIn(command->add_option("--cutoff", a->smoothOptions.cutoffHz, "Butterworth cut-off frequency")
               ->type_name("HZ"),
           1e-6, 1e6)
      ->capture_default_str();
  command
      ->add_option("--stabilize", a->stabilize,
                   "head-mounted markers whose motion is removed first; with no labels, the head markers saved in "
                   "IN (refused when it has none: nothing is guessed)")
      ->type_name("[LABEL,...]")
      ->expected(0, 1);
  command->add_flag("--keep-stabilized", a->keepStabilized, "write the markers in head space");
  command->add_option("--report", a->report, "write a JSON report of every step and every gap")
      ->type_name("FILE.json");
  CLI::Option* preset =
      command->add_option("--preset", a->preset, "the cleaning options from a preset (mocap batch --preset)")
          ->type_name("PRESET.json");
  for (CLI::Option* option : command->get_options())
    if (option != preset && option != input && option->get_name() != "--output" && option->get_name() != "--report" &&
        option->get_name() != "--help" && option->get_name() != "-h")
      preset->excludes(option);
  CLI::Option* manifest = command
                              ->add_option("--manifest", a->manifest,
                                           "clean one take of a mocap batch manifest into OUTDIR, as the batch would")
                              ->type_name("F")
                              ->excludes(input);
  wholeNumberIn(command->add_option("--index", a->index,
                                    "the manifest's take to clean, 0-based (blank, # and repeated lines do not "
                                    "count); default: $SLURM_ARRAY_TASK_ID or $JOB_COMPLETION_INDEX")
                    ->type_name("I")
                    ->needs(manifest),
                0, 1LL << 40);
  command->add_flag("--resume", a->resume, "with --manifest: skip the take when OUTDIR holds it from the same input and preset");
  command->add_flag("--count", a->count, "with --manifest: print how many takes it lists (the job array's size) and exit")
      ->needs(manifest)
      ->excludes(command->get_option("--index"));
  numberIn(command->add_option("--min-valid-after", a->minValidAfter,
                               "quality check: exit 3 when the valid fraction after cleaning is below F (the take "
                               "is still written; mocap batch --min-valid)")
               ->type_name("F"),
           0.0, 1.0);
  return {command, [a] { return runClean(*a); }};
}

} // namespace mocap::cli
