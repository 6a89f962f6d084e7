#pragma once

#include "mocap/model/take.h"

#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// The history step operation that records data a reader found lost or wrong in a file
/// (truncation, a misread layout, coordinates that wrapped round): parameter "finding" holds the
/// reader's words, "file" the file's name.
inline constexpr std::string_view kDataLossOperation = "data lost on reading";

/// Makes a read's data-loss findings travel with the take, so that saving it (to a file whose own
/// bytes no longer show the problem, e.g. a float C3D after an integer one whose words wrapped)
/// never passes the samples off as sound. Each finding of this read (`dataLoss` from index
/// `firstNew` on) that the take's history does not hold yet becomes a history step of
/// kDataLossOperation, tool "mocap reader", from `source` (a path; its file name is kept), written
/// with the take's PROCESSING group or sidecar. Each such step the history already held (read
/// from the file) whose finding this read did not make again is added to `dataLoss` as "recorded
/// when FILE was read: FINDING" (and to `warnings` when given), so every reader of the saved file
/// reports it as data loss. O(#history · #findings).
void carryDataLoss(Take& take, const std::string& source, std::vector<std::string>& dataLoss, std::size_t firstNew,
                   std::vector<std::string>* warnings);

} // namespace mocap
