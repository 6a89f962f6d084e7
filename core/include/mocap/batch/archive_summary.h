#pragma once

#include "mocap/batch/take_report.h"

#include <filesystem>
#include <string>
#include <vector>

namespace mocap {

/// A take the archive report sends to a person, with why.
struct TakeToReview
{
  std::size_t take = 0;  ///< index into ArchiveSummary::reports
  std::string reason;    ///< e.g. "failed: …", "valid 0.62 after cleaning (< 0.9); 3 gaps left open"
  double severity = 0.0; ///< larger is worse: failures first, then by the valid fraction missing
};

/// Every per-take report under a batch's OUTDIR, for `mocap summarize`.
struct ArchiveSummary
{
  std::filesystem::path outDir;
  std::vector<TakeReport> reports;  ///< sorted by output path
  /// Report files that could not be read, "path: error".
  std::vector<std::string> unreadable;
  double minValid = 0.9;  ///< a take below this valid fraction after cleaning needs a person
  std::vector<TakeToReview> review;  ///< worst first
};

/// Reads every "*.report.json" below `outDir` (recursively, in path order) and ranks the takes
/// that need a person: failed ones, then valid fraction after cleaning below `minValid`, markers
/// with no valid sample, gaps left open. Throws IoError when `outDir` is not a readable folder.
/// O(#reports · report size).
[[nodiscard]] ArchiveSummary summarizeArchive(const std::filesystem::path& outDir, double minValid);

/// Failed takes that failed for one reason (e.g. "the take has no marker labelled 'head1'").
struct FailureGroup
{
  std::string reason;              ///< the error, less a leading "TAKE: " naming the take itself
  std::vector<std::size_t> takes;  ///< indices into ArchiveSummary::reports, in report order
};

/// The failed takes grouped by reason, the largest group first (then by reason), so one cause
/// behind many failures (a preset's head markers the takes lack) reads as one line.
/// O(#takes · log #takes).
[[nodiscard]] std::vector<FailureGroup> failuresByReason(const ArchiveSummary& summary);

/// One self-contained HTML page (inline SVG, no script, no network; well-formed XML so any parser
/// reads it): counts, valid fraction before and after per take, a histogram of gap lengths,
/// spikes per marker, a heat map of missing samples (markers × takes), the failures by reason, the
/// takes to review and the presets used. O(#takes · #markers).
[[nodiscard]] std::string archiveSummaryHtml(const ArchiveSummary& summary);

/// The same figures as JSON (counts, per-take valid fractions, the gap-length histogram, spikes
/// per marker, "failures_by_reason", the takes to review, the presets by hash). O(#takes · #markers).
[[nodiscard]] std::string archiveSummaryJson(const ArchiveSummary& summary);

} // namespace mocap
