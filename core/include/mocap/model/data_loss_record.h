#pragma once

#include "mocap/model/processing_step.h"
#include "mocap/model/take.h"

#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// The history step operation that records data a reader found lost or wrong in a file
/// (truncation, a misread layout, coordinates that wrapped round): parameter "finding" holds the
/// reader's words, "file" the file's name.
inline constexpr std::string_view kDataLossOperation = "data lost on reading";
/// The history step operation by which a person acknowledged a data-loss step (same "file" and
/// "finding" parameters): the finding stays in the take's history and `mocap info`, but later
/// reads no longer raise it as a warning, nor `mocap summarize` as a take that needs a person.
inline constexpr std::string_view kDataLossAcknowledgedOperation = "data loss acknowledged";

/// What a data-loss finding says of the take's samples.
enum class DataLossKind
{
  Missing,  ///< declared data is not in the take (a truncated file, a data section shorter than declared)
  Wrong,    ///< samples are in the take but are not what was captured (wrapped coordinates, a misread layout)
};

/// The kind of a reader's finding, or of a carried one ("recorded when FILE was read: FINDING",
/// judged by FINDING alone). The readers word every finding of missing data with "truncated" or
/// "shorter than declared" (c3d_reader, trc_io); any other finding is of wrong data, the claim
/// that never understates it. O(#finding).
[[nodiscard]] DataLossKind dataLossKind(std::string_view finding);
/// "missing" or "wrong" (the JSON's and the tests' name of a kind). O(1).
[[nodiscard]] std::string_view dataLossKindName(DataLossKind kind);

/// Which kinds a list of findings holds.
struct DataLossKinds
{
  bool missing = false;
  bool wrong = false;
};
[[nodiscard]] DataLossKinds dataLossKinds(const std::vector<std::string>& findings);

/// A data-loss step of a take's history, and whether a later step acknowledged it.
struct DataLossRecord
{
  std::string file;     ///< the name of the file whose read found it
  std::string finding;  ///< the reader's words
  bool acknowledged = false;
};

/// Every data-loss step of `take`'s history, oldest first; acknowledged when a later
/// kDataLossAcknowledgedOperation step names the same file and finding. O(#history²).
[[nodiscard]] std::vector<DataLossRecord> dataLossRecords(const Take& take);

/// "recorded when FILE was read: FINDING": how a later read reports a record.
[[nodiscard]] std::string recordedFindingText(const DataLossRecord& record);

/// The step acknowledging `record` (operation kDataLossAcknowledgedOperation, its file and
/// finding as parameters), by `tool` at `time`.
[[nodiscard]] ProcessingStep acknowledgementOf(const DataLossRecord& record, std::string tool, std::string time);

/// Makes a read's data-loss findings travel with the take, so that saving it (to a file whose own
/// bytes no longer show the problem, e.g. a float C3D after an integer one whose words wrapped)
/// never passes the samples off as sound. Each finding of this read (`dataLoss` from index
/// `firstNew` on) that the take's history does not hold yet becomes a history step of
/// kDataLossOperation, tool "mocap reader", from `source` (a path; its file name is kept), written
/// with the take's PROCESSING group or sidecar. Each such step the history already held (read
/// from the file) whose finding this read did not make again and that nobody acknowledged is
/// added to `dataLoss` as recordedFindingText (and to `warnings` when given), so every reader of
/// the saved file reports it as data loss. O(#history² + #history · #findings).
void carryDataLoss(Take& take, const std::string& source, std::vector<std::string>& dataLoss, std::size_t firstNew,
                   std::vector<std::string>* warnings);

} // namespace mocap
