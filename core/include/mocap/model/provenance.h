#pragma once

#include "mocap/model/c3d_parameters.h"
#include "mocap/model/processing_step.h"
#include "mocap/model/take.h"

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <optional>
#include <vector>

namespace mocap {

class JsonWriter;

/// Provenance: which samples of a take were measured and which were made (filled, edited), what
/// was done to them since (smoothed, stabilized), and the processing history that did it. Stored
/// compactly as run-length ranges: in C3D files in the project's own parameter group PROCESSING (other readers skip unknown
/// groups), beside TRC/CSV files in a sidecar NAME.provenance.json with the same content.
///
/// PROCESSING group (written only when there is something to say):
///   VERSION     Int16 scalar, 2
///   LABELS      Char, the marker labels the runs refer to (POINT:LABELS at write time)
///   STATE_RUNS  Float [4, n], n ≤ 255, continued in STATE_RUNS2, STATE_RUNS3…: per run the
///               marker index into LABELS, the first frame (0-based), the length and the state:
///               the origin (0 measured, 1 filled, 3 edited) plus 4 when smoothed and 8 when
///               stabilized, e.g. 5 = filled then smoothed; floats hold these exactly up to 2^24.
///               VERSION 1 (read, no longer written) kept one state per sample: 1 filled,
///               2 smoothed (read as measured + smoothed), 3 edited
///   HISTORY     Char [255, n], continued in HISTORY2…: the history as a JSON array, in
///               255-byte pieces; HISTORY_BYTES (Float scalar) is its length
///   HEAD_MARKERS Char, the labels of the take's head reference markers (headMarkers below),
///               written only when chosen; a file without it has none
/// Filled samples are also written with residual 0 (the C3D convention for computed points).

/// A run of consecutive frames of one marker in the same state, not measured-and-untouched.
struct StateRun
{
  Eigen::Index marker = 0;
  Eigen::Index first = 0;  ///< 0-based frame index
  Eigen::Index length = 0;
  SampleState state = SampleOrigin::Filled;

  friend bool operator==(const StateRun& a, const StateRun& b)
  {
    return a.marker == b.marker && a.first == b.first && a.length == b.length && a.state == b.state;
  }
};

/// The runs of samples that are not measured-and-untouched, marker by marker in frame order.
/// O(#frames · #markers).
[[nodiscard]] std::vector<StateRun> stateRuns(const Take& take);

/// How many samples of one marker have each origin and each operation. The origins partition
/// the samples that count (a sample has one origin); the operations overlap them (a filled
/// sample that was smoothed counts in `filled` and in `smoothed`).
struct StateCounts
{
  Eigen::Index measured = 0;    ///< valid samples as captured (smoothed or stabilized or not)
  Eigen::Index filled = 0;      ///< samples invented for gaps
  Eigen::Index edited = 0;      ///< samples replaced or deleted by a person or a repair
  Eigen::Index smoothed = 0;    ///< samples moved by smoothing, whatever their origin
  Eigen::Index stabilized = 0;  ///< samples held in the head frame, whatever their origin
  /// Measured samples that were smoothed: the "smoothed" of version 1 counts, where each sample
  /// had one state, so filled + smoothedMeasured + edited still counts each made sample once.
  Eigen::Index smoothedMeasured = 0;

  StateCounts& operator+=(const StateCounts& other);
};

/// One StateCounts per marker. O(#frames · #markers).
[[nodiscard]] std::vector<StateCounts> stateCounts(const Take& take);

/// The sum over markers. O(#markers).
[[nodiscard]] StateCounts totalCounts(const std::vector<StateCounts>& counts);

/// True when some sample is not measured-and-untouched, the take has a history or head markers.
/// O(#frames · #markers).
[[nodiscard]] bool hasProvenance(const Take& take);

/// The operations a SampleState can carry, in the order names are listed.
inline constexpr std::array<SampleOperation, 2> kSampleOperations{SampleOperation::Smoothed,
                                                                  SampleOperation::Stabilized};

/// "measured", "filled", "edited". O(1).
[[nodiscard]] std::string_view sampleOriginName(SampleOrigin origin);
/// "smoothed", "stabilized". O(1).
[[nodiscard]] std::string_view sampleOperationName(SampleOperation operation);
/// The origin or operation sampleOriginName / sampleOperationName gives `name`, or nullopt. O(1).
[[nodiscard]] std::optional<SampleOrigin> parseSampleOrigin(std::string_view name);
[[nodiscard]] std::optional<SampleOperation> parseSampleOperation(std::string_view name);

/// Writes `counts` as members of the open JSON object: "filled", "smoothed", "edited" as version 1
/// counted them (each sample once, by origin first: "smoothed" is smoothedMeasured), then
/// "origin": {"measured", "filled", "edited"} and "operations": {"smoothed", "stabilized"}.
/// O(1).
void writeStateCountsJson(JsonWriter& json, const StateCounts& counts);

/// Writes `history` as a JSON array of objects (operation, parameters, markers, first_frame,
/// last_frame, samples, time, tool). O(history size).
void writeHistoryJson(JsonWriter& json, const std::vector<ProcessingStep>& history);

/// The sidecar document: {"format": "mocap-studio provenance", "version": 2, "frames",
/// "first_frame", "markers": [{"label", counts as writeStateCountsJson, "runs": [[first_frame,
/// length, origin, [operation, …]], …]}], "history": […], "head_markers": [label, …]} with frames
/// in the take's numbering ("head_markers" only when chosen), e.g. a run [120, 14, "filled",
/// ["smoothed"]]. Version 1 runs were [first_frame, length, state] with one state of "filled",
/// "smoothed", "edited". O(#frames · #markers).
[[nodiscard]] std::string provenanceJson(const Take& take);

/// Puts the states, history and head markers of a provenance document (version 1 or 2) into
/// `take` (markers matched by label; a label the take lacks, a run outside the take or with an
/// unknown state, or another frame count is skipped with a warning, a head marker the take lacks
/// too). Throws FormatError for text that is not a provenance document.
/// O(document size + #frames · #markers).
void applyProvenanceJson(Take& take, std::string_view text, const std::string& sourceName,
                         std::vector<std::string>* warnings);

/// Replaces the PROCESSING group of `tree` with `take`'s provenance (removes it when the take
/// has none). O(#frames · #markers).
void storeProvenance(const Take& take, C3dParameterTree& tree);

/// Moves the PROCESSING group (VERSION 1 or 2) of take.parameters() into the take's states and
/// history and removes the group but its HEAD_MARKERS (the writer makes it anew); another VERSION
/// is a warning and only its history is read. A file without one that has real residuals (some
/// valid sample above 0, fewer than half at 0) gets its residual-0 samples marked Filled,
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
