#pragma once

#include "mocap/batch/take_manifest.h"
#include "mocap/batch/take_report.h"
#include "mocap/cleaning/clean_pipeline.h"

#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mocap {

/// How far a batch got, handed to BatchOptions::progress after each take.
struct BatchProgress
{
  std::size_t total = 0;
  std::size_t done = 0;     ///< takes finished, whatever the outcome (skipped ones included)
  std::size_t skipped = 0;  ///< --resume found them done already
  std::size_t failed = 0;   ///< could not be processed
  std::size_t lowQuality = 0;
  double seconds = 0.0;     ///< since the batch started
};

struct BatchOptions
{
  std::filesystem::path outDir;
  CleanOptions preset;
  int jobs = 0;         ///< takes cleaned at once; ≤ 0: one per core
  bool resume = false;  ///< skip takes whose output exists and whose report has the same hashes
  /// A take whose valid fraction after cleaning is below this fails the quality check (its
  /// output is kept, the batch exits 3).
  std::optional<double> minValid;
  /// Set (e.g. by SIGINT) to stop: no new take starts, takes in progress finish, nothing partial.
  const std::atomic<bool>* cancel = nullptr;
  /// Called after each take, from the thread that finished it, one call at a time.
  std::function<void(const BatchProgress&)> progress;
  std::string tool = "mocap batch";  ///< the history steps' tool
};

/// What became of one take.
enum class TakeStatus
{
  Cleaned,  ///< cleaned and written
  Skipped,  ///< --resume: already done with this input and preset
  Failed,   ///< could not be read, cleaned or written (error says why; nothing partial left)
  NotRun,   ///< the batch was stopped before it started
};
[[nodiscard]] std::string_view takeStatusName(TakeStatus status);

struct BatchTakeResult
{
  TakeStatus status = TakeStatus::NotRun;
  std::string error;
  bool lowQuality = false;  ///< valid fraction after cleaning below BatchOptions::minValid
  double validAfter = 0.0;
  double seconds = 0.0;
};

struct BatchResult
{
  std::vector<BatchTakeResult> takes;  ///< one per manifest take, in its order
  bool cancelled = false;
  double seconds = 0.0;
  std::int64_t inputBytes = 0;  ///< bytes read by the takes processed (not skipped)
  [[nodiscard]] std::size_t count(TakeStatus status) const;
  [[nodiscard]] std::size_t lowQualityCount() const;
};

/// Cleans take `index` of `manifest` with `options.preset` into `options.outDir` (takeOutputs):
/// the take, then its report, each written atomically, so an interruption leaves the old files
/// or the complete new ones. A take that fails gets a report with its error (and no take file;
/// a stale one from an earlier run is removed). With `options.resume`, a take whose output exists
/// and whose report records the same input hash and preset hash is skipped. Never throws for a
/// bad take; throws IoError only when the report itself cannot be written. Cost: reading and
/// hashing the input, cleanTake, writing.
/// Call prepareOutDir first.
BatchTakeResult runBatchTake(const TakeManifest& manifest, std::size_t index, const BatchOptions& options);

/// Throws InvalidArgument when `outDir` is the manifest's root (the outputs would overwrite the
/// inputs) and IoError when it cannot be created. O(path length).
void prepareOutDir(const TakeManifest& manifest, const std::filesystem::path& outDir);

/// The order runBatch hands the takes to its jobs: the largest input first (ties and unreadable
/// files in manifest order), so that a long take does not start last and leave the other jobs
/// idle while it runs (longest-processing-time-first scheduling; the results are stored by
/// index, so the files written do not depend on it). O(n log n) after one stat per take.
[[nodiscard]] std::vector<std::size_t> batchTakeOrder(const TakeManifest& manifest);

/// runBatchTake for every take, `options.jobs` at a time (parallelFor; each take on one thread, so
/// the files written do not depend on the number of jobs; the largest inputs start first), then
/// OUTDIR/batch.json (batchReportJson).
/// Throws InvalidArgument when OUTDIR would overwrite the inputs and IoError when OUTDIR cannot be
/// created or written. A stop via `options.cancel` returns with cancelled set.
[[nodiscard]] BatchResult runBatch(const TakeManifest& manifest, const BatchOptions& options);

/// The batch report: the manifest, OUTDIR, the preset and its hash, the counts, and every take
/// with its status ("cleaned", "skipped", "failed", "not_run"), error, quality flag and output
/// paths. O(#takes).
[[nodiscard]] std::string batchReportJson(const TakeManifest& manifest, const BatchOptions& options,
                                          const BatchResult& result);

/// The batch report's file name in OUTDIR, "batch.json".
[[nodiscard]] const std::string& batchReportName();

} // namespace mocap
