#pragma once

#include "mocap/model/c3d_parameters.h"
#include "mocap/model/processing_step.h"
#include "mocap/model/take.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <optional>
#include <vector>

namespace mocap {

class JsonWriter;

/// Provenance: which samples of a take were measured and which were made (filled, smoothed,
/// edited), and the processing history that made them. Stored compactly as run-length ranges:
/// in C3D files in the project's own parameter group PROCESSING (other readers skip unknown
/// groups), beside TRC/CSV files in a sidecar NAME.provenance.json with the same content.
///
/// PROCESSING group (written only when there is something to say):
///   VERSION     Int16 scalar, 1
///   LABELS      Char, the marker labels the runs refer to (POINT:LABELS at write time)
///   STATE_RUNS  Float [4, n], n ≤ 255, continued in STATE_RUNS2, STATE_RUNS3…: per run the
///               marker index into LABELS, the first frame (0-based), the length and the state
///               (1 filled, 2 smoothed, 3 edited); floats hold these exactly up to 2^24
///   HISTORY     Char [255, n], continued in HISTORY2…: the history as a JSON array, in
///               255-byte pieces; HISTORY_BYTES (Float scalar) is its length
///   HEAD_MARKERS Char, the labels of the take's head reference markers (headMarkers below),
///               written only when chosen; a file without it has none (VERSION stays 1)
/// Filled samples are also written with residual 0 (the C3D convention for computed points).

/// A run of consecutive frames of one marker in the same non-original state.
struct StateRun
{
  Eigen::Index marker = 0;
  Eigen::Index first = 0;  ///< 0-based frame index
  Eigen::Index length = 0;
  SampleState state = SampleState::Filled;

  friend bool operator==(const StateRun& a, const StateRun& b)
  {
    return a.marker == b.marker && a.first == b.first && a.length == b.length && a.state == b.state;
  }
};

/// The runs of non-original samples, marker by marker in frame order. O(#frames · #markers).
[[nodiscard]] std::vector<StateRun> stateRuns(const Take& take);

/// How many samples of one marker are in each non-original state.
struct StateCounts
{
  Eigen::Index filled = 0;
  Eigen::Index smoothed = 0;
  Eigen::Index edited = 0;
};

/// One StateCounts per marker. O(#frames · #markers).
[[nodiscard]] std::vector<StateCounts> stateCounts(const Take& take);

/// True when some sample is not original, the take has a history or head markers.
/// O(#frames · #markers).
[[nodiscard]] bool hasProvenance(const Take& take);

/// "original", "filled", "smoothed", "edited". O(1).
[[nodiscard]] std::string_view sampleStateName(SampleState state);

/// Writes `history` as a JSON array of objects (operation, parameters, markers, first_frame,
/// last_frame, samples, time, tool). O(history size).
void writeHistoryJson(JsonWriter& json, const std::vector<ProcessingStep>& history);

/// The sidecar document: {"format": "mocap-studio provenance", "version": 1, "frames",
/// "first_frame", "markers": [{"label", "filled", "smoothed", "edited", "runs": [[first_frame,
/// length, state], …]}], "history": […], "head_markers": [label, …]} with frames in the take's
/// numbering ("head_markers" only when chosen). O(#frames · #markers).
[[nodiscard]] std::string provenanceJson(const Take& take);

/// Puts the states and history of a provenance document into `take` (markers matched by
/// label; a label the take lacks, a run outside the take or another frame count is skipped
/// with a warning, a head marker the take lacks too). Throws FormatError for text that is not a provenance document.
/// O(document size + #frames · #markers).
void applyProvenanceJson(Take& take, std::string_view text, const std::string& sourceName,
                         std::vector<std::string>* warnings);

/// Replaces the PROCESSING group of `tree` with `take`'s provenance (removes it when the take
/// has none). O(#frames · #markers).
void storeProvenance(const Take& take, C3dParameterTree& tree);

/// Moves the PROCESSING group of take.parameters() into the take's states and history and
/// removes the group but its HEAD_MARKERS (the writer makes it anew). A file without one that has real residuals
/// (some valid sample above 0, fewer than half at 0) gets its residual-0 samples marked Filled,
/// the C3D convention for computed points, with a warning saying how many. A malformed group
/// is skipped with a warning. O(#frames · #markers); O(1) for a file without the group when
/// the reader passes the residual counts it made while decoding.
struct ResidualCounts
{
  Eigen::Index zero = 0;   ///< valid samples with residual 0
  Eigen::Index valid = 0;  ///< valid samples
};
void loadProvenance(Take& take, std::vector<std::string>* warnings,
                    std::optional<ResidualCounts> counts = std::nullopt);

/// The labels of the take's head reference markers as chosen (the studio's Marker ▸ Reference
/// Markers…), empty when nobody chose them. Kept in take.parameters() as PROCESSING:HEAD_MARKERS,
/// the one part of the group that stays in the tree after loadProvenance (the rest becomes the
/// take's states and history), so they travel with every copy of the take and every writer saves
/// them (C3D in the group, TRC/CSV in the sidecar). A marker renamed later is not followed: the
/// studio's document stores the set again after each edit. O(#labels).
[[nodiscard]] std::vector<std::string> headMarkers(const Take& take);
/// Sets them; empty removes them (and the group from the tree when nothing else is in it).
/// O(#labels).
void setHeadMarkers(Take& take, const std::vector<std::string>& labels);

/// Where the provenance of a TRC/CSV file is kept: NAME.provenance.json beside NAME.trc. O(1).
[[nodiscard]] std::filesystem::path provenanceSidecarPath(const std::filesystem::path& takePath);

} // namespace mocap
