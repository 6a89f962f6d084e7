#include "mocap/batch/batch_runner.h"

#include "mocap/base/content_hash.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_writer.h"
#include "mocap/base/parallel_for.h"
#include "mocap/base/stopwatch.h"
#include "mocap/batch/clean_preset.h"
#include "mocap/batch/clean_run.h"
#include "mocap/io/take_io.h"
#include "mocap/model/marker_points.h"

#include <algorithm>
#include <mutex>
#include <numeric>
#include <system_error>

namespace fs = std::filesystem;

namespace mocap {

namespace {

/// Whether the report at `path` says the take was cleaned from the same bytes with the same
/// preset; an unreadable or foreign report is not (the take is cleaned again).
std::optional<TakeReport> finishedBefore(const TakeOutputs& outputs, const std::string& inputHash,
                                         const std::string& presetHash)
{
  std::error_code error;
  if (!fs::is_regular_file(outputs.take, error) || !fs::is_regular_file(outputs.report, error))
    return std::nullopt;
  try {
    TakeReport report = parseTakeReport(readFileBytes(outputs.report), outputs.report.string());
    if (!report.failed() && report.inputHash == inputHash && report.presetHash == presetHash)
      return report;
  } catch (const Error&) {
  }
  return std::nullopt;
}

void ensureFolder(const fs::path& folder)
{
  std::error_code error;
  fs::create_directories(folder, error);
  if (!fs::is_directory(folder))
    throw IoError(folder.string() + ": cannot create the folder (" +
                  (error ? error.message() : std::string("a file is in the way")) + ")");
}

bool lowQuality(const BatchOptions& options, double validAfter)
{
  return options.minValid && validAfter < *options.minValid;
}

} // namespace

std::string_view takeStatusName(TakeStatus status)
{
  switch (status) {
  case TakeStatus::Cleaned: return "cleaned";
  case TakeStatus::Skipped: return "skipped";
  case TakeStatus::Failed: return "failed";
  case TakeStatus::NotRun: return "not_run";
  }
  return "not_run";
}

std::size_t BatchResult::count(TakeStatus status) const
{
  std::size_t n = 0;
  for (const BatchTakeResult& take : takes)
    n += take.status == status ? 1 : 0;
  return n;
}

std::size_t BatchResult::lowQualityCount() const
{
  std::size_t n = 0;
  for (const BatchTakeResult& take : takes)
    n += take.lowQuality ? 1 : 0;
  return n;
}

const std::string& batchReportName()
{
  static const std::string name = "batch.json";
  return name;
}

BatchTakeResult runBatchTake(const TakeManifest& manifest, std::size_t index, const BatchOptions& options)
{
  const Stopwatch total;
  const ManifestEntry& entry = manifest.takes.at(index);
  const TakeOutputs outputs = takeOutputs(entry, options.outDir);
  TakeReport report;
  report.input = entry.input.string();
  report.output = entry.relative.string();
  report.preset = options.preset;
  report.presetHash = cleanPresetHash(options.preset);
  BatchTakeResult result;
  try {
    ensureFolder(outputs.take.parent_path());
  } catch (const Error& e) {
    result.status = TakeStatus::Failed;
    result.error = e.what();
    return result;
  }
  try {
    Stopwatch step;
    {
      const MappedFile bytes(entry.input);
      report.inputBytes = static_cast<std::int64_t>(bytes.size());
      report.inputHash = hashText(contentHash({reinterpret_cast<const char*>(bytes.data()), bytes.size()}));
    }
    if (options.resume)
      if (const std::optional<TakeReport> before = finishedBefore(outputs, report.inputHash, report.presetHash)) {
        result.status = TakeStatus::Skipped;
        result.validAfter = before->validAfter;
        result.lowQuality = lowQuality(options, before->validAfter);
        result.seconds = total.seconds();
        return result;
      }
    Take take = readTake(entry.input, &report.warnings, &report.dataLoss);
    report.timings.read = step.seconds();
    step = Stopwatch();
    report.validBefore = markerValidFraction(take);
    std::vector<MarkerQuality> before = qualityBefore(take);
    const CleanReport cleaning = cleanAndRecord(take, options.preset, options.tool);
    recordCleaning(report, std::move(before), take, cleaning);
    report.timings.clean = step.seconds();
    step = Stopwatch();
    writeCleanedTake(take, cleaning, options.preset, outputs.take);
    report.timings.write = step.seconds();
  } catch (const std::exception& e) {
    report.error = e.what();
    std::error_code ignored;
    fs::remove(outputs.take, ignored);  // no stale output beside a report saying it failed
  }
  report.timings.total = total.seconds();
  try {
    writeFileAtomically(outputs.report, takeReportJson(report));
  } catch (const std::exception& e) {
    // A take without its report would look done to nobody and undone to --resume: drop it.
    std::error_code ignored;
    fs::remove(outputs.take, ignored);
    report.error = report.failed() ? report.error + "; " + e.what() : e.what();
  }
  result.status = report.failed() ? TakeStatus::Failed : TakeStatus::Cleaned;
  result.error = report.error;
  result.validAfter = report.validAfter;
  result.lowQuality = !report.failed() && lowQuality(options, report.validAfter);
  result.seconds = total.seconds();
  return result;
}

std::string batchReportJson(const TakeManifest& manifest, const BatchOptions& options, const BatchResult& result)
{
  JsonWriter json;
  json.beginObject();
  json.key("format").value("mocap-batch-report");
  json.key("version").value(1);
  json.key("manifest").value(fs::absolute(manifest.source).lexically_normal().string());
  json.key("root").value(manifest.root.string());
  json.key("out_dir").value(fs::absolute(options.outDir).lexically_normal().string());
  json.key("finished").value(!result.cancelled && result.count(TakeStatus::NotRun) == 0);
  json.key("cancelled").value(result.cancelled);
  json.key("seconds").value(result.seconds);
  json.key("counts").beginObject();
  json.key("total").value(static_cast<std::int64_t>(result.takes.size()));
  for (const TakeStatus status : {TakeStatus::Cleaned, TakeStatus::Skipped, TakeStatus::Failed, TakeStatus::NotRun})
    json.key(takeStatusName(status)).value(static_cast<std::int64_t>(result.count(status)));
  json.key("low_quality").value(static_cast<std::int64_t>(result.lowQualityCount()));
  json.endObject();
  if (options.minValid)
    json.key("min_valid").value(*options.minValid);
  else
    json.key("min_valid").null();
  json.key("warnings").beginArray();
  for (const std::string& warning : manifest.warnings)
    json.value(warning);
  json.endArray();
  json.key("preset_hash").value(cleanPresetHash(options.preset));
  json.key("preset");
  writeCleanPreset(json, options.preset);
  json.key("takes").beginArray();
  for (std::size_t i = 0; i < manifest.takes.size(); ++i) {
    const ManifestEntry& entry = manifest.takes[i];
    const BatchTakeResult& take = result.takes.at(i);
    json.beginObject();
    json.key("index").value(static_cast<std::int64_t>(i));
    if (entry.line > 0)
      json.key("line").value(static_cast<std::int64_t>(entry.line));
    json.key("input").value(entry.input.string());
    json.key("output").value(entry.relative.string());
    json.key("report").value(entry.relative.string() + takeReportSuffix());
    json.key("status").value(takeStatusName(take.status));
    if (!take.error.empty())
      json.key("error").value(take.error);
    if (take.status == TakeStatus::Cleaned || take.status == TakeStatus::Skipped) {
      json.key("valid_fraction_after").value(take.validAfter);
      json.key("low_quality").value(take.lowQuality);
    }
    json.key("seconds").value(take.seconds);
    json.endObject();
  }
  json.endArray();
  json.endObject();
  return json.str() + "\n";
}

void prepareOutDir(const TakeManifest& manifest, const fs::path& outDir)
{
  std::error_code error;
  const fs::path out = fs::weakly_canonical(fs::absolute(outDir), error);
  const fs::path root = fs::weakly_canonical(manifest.root, error);
  if (!out.empty() && out == root)
    throw InvalidArgument(outDir.string() + ": OUTDIR is the inputs' folder; the cleaned takes would overwrite them");
  ensureFolder(outDir);
}

std::vector<std::size_t> batchTakeOrder(const TakeManifest& manifest)
{
  std::vector<std::uintmax_t> sizes(manifest.takes.size(), 0);
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    std::error_code error;
    const std::uintmax_t size = fs::file_size(manifest.takes[i].input, error);
    sizes[i] = error ? 0 : size;
  }
  std::vector<std::size_t> order(sizes.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return sizes[a] > sizes[b]; });
  return order;
}

BatchResult runBatch(const TakeManifest& manifest, const BatchOptions& options)
{
  const Stopwatch clock;
  prepareOutDir(manifest, options.outDir);
  BatchResult result;
  result.takes.resize(manifest.takes.size());
  const fs::path reportPath = options.outDir / batchReportName();
  // Written first as well: OUTDIR is known writable before any take runs, and a batch killed
  // outright still leaves a report saying which takes were not run.
  writeFileAtomically(reportPath, batchReportJson(manifest, options, result));

  std::mutex progressMutex;
  BatchProgress progress;
  progress.total = manifest.takes.size();
  const std::vector<std::size_t> order = batchTakeOrder(manifest);
  const auto body = [&](std::size_t k) {
    const std::size_t i = order[k];
    BatchTakeResult take = runBatchTake(manifest, i, options);
    const std::lock_guard<std::mutex> lock(progressMutex);
    ++progress.done;
    progress.skipped += take.status == TakeStatus::Skipped ? 1 : 0;
    progress.failed += take.status == TakeStatus::Failed ? 1 : 0;
    progress.lowQuality += take.lowQuality ? 1 : 0;
    progress.seconds = clock.seconds();
    result.takes[i] = std::move(take);
    if (options.progress)
      options.progress(progress);
  };
  result.cancelled = !parallelFor(manifest.takes.size(), options.jobs, body, options.cancel);
  result.seconds = clock.seconds();
  for (std::size_t i = 0; i < manifest.takes.size(); ++i)
    if (result.takes[i].status == TakeStatus::Cleaned || result.takes[i].status == TakeStatus::Failed) {
      std::error_code sizeError;
      const auto size = fs::file_size(manifest.takes[i].input, sizeError);
      result.inputBytes += sizeError ? 0 : static_cast<std::int64_t>(size);
    }
  writeFileAtomically(reportPath, batchReportJson(manifest, options, result));
  return result;
}

} // namespace mocap
