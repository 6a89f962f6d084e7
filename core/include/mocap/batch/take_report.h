#pragma once

#include "mocap/cleaning/clean_pipeline.h"
#include "mocap/model/take.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// One marker of a per-take report.
struct MarkerQuality
{
  std::string label;
  double validBefore = 0.0;  ///< fraction of frames valid as read
  double validAfter = 0.0;   ///< after cleaning
  std::vector<std::int64_t> gapLengths;  ///< every gap as read, in frames, in frame order
  std::int64_t spikes = 0;               ///< samples flagged as spikes (and repaired)
  std::int64_t filledGaps = 0;
  std::int64_t unfilledGaps = 0;
};

/// Seconds spent on the steps of one take (not part of the take's result: they differ per run).
struct TakeTimings
{
  double read = 0.0, clean = 0.0, write = 0.0, total = 0.0;
};

/// The per-take JSON report of a batch, written beside the cleaned take: what went in (path,
/// content hash, the preset and its hash), what came out and the quality before and after.
/// A take that failed has `error` set and no quality figures.
struct TakeReport
{
  std::string input;       ///< as the manifest resolved it (absolute)
  std::string output;      ///< the cleaned take, relative to OUTDIR
  std::string inputHash;   ///< contentHash of the input file's bytes (hex); "" when unreadable
  std::string presetHash;  ///< cleanPresetHash of `preset`
  CleanOptions preset;
  std::string error;       ///< why it failed; empty when it was cleaned
  std::vector<std::string> warnings;  ///< what the reader tolerated (header/parameter conflicts among them)
  std::vector<std::string> dataLoss;  ///< of those, the ones meaning data the file declares is missing
  std::int64_t inputBytes = 0;
  std::int64_t frames = 0;
  double frameRate = 0.0;
  double validBefore = 0.0;
  double validAfter = 0.0;
  std::int64_t spikes = 0;         ///< samples flagged
  std::int64_t filledGaps = 0;
  std::int64_t unfilledGaps = 0;
  std::int64_t filledSamples = 0;
  std::int64_t smoothedSamples = 0;
  std::vector<std::string> missingMarkers;  ///< markers with no valid sample after cleaning
  std::int64_t modelOutputs = 0;            ///< points cleaning left untouched (angles, forces...)
  std::vector<MarkerQuality> markers;
  TakeTimings timings;

  [[nodiscard]] bool failed() const { return !error.empty(); }
};

/// The valid fraction and gaps of every marker point of `take` (model outputs are left out,
/// marker_points.h) as read, before cleaning. O(#frames · #markers).
[[nodiscard]] std::vector<MarkerQuality> qualityBefore(const Take& take);

/// Completes `report` from the markers as read (`before`), the cleaned take and what the pipeline
/// did (validBefore is the caller's: markerValidFraction of the take as read): valid fractions after, spikes and filled/unfilled gaps per marker, markers missing.
/// O(#frames · #markers + #spikes + #gaps).
void recordCleaning(TakeReport& report, std::vector<MarkerQuality> before, const Take& cleaned,
                    const CleanReport& cleaning);

/// The report as JSON (keys in a fixed order; "timings" last, the only part that differs between
/// two runs of the same take and preset). O(size).
[[nodiscard]] std::string takeReportJson(const TakeReport& report);

/// Reads a report written by takeReportJson. Throws FormatError / InvalidArgument naming
/// `sourceName` and the key for text that is not such a report. O(size).
[[nodiscard]] TakeReport parseTakeReport(std::string_view text, const std::string& sourceName);

} // namespace mocap
