#pragma once

#include "mocap/cleaning/clean_pipeline.h"

#include <filesystem>
#include <string>

namespace mocap {

/// One take cleaned the way `mocap clean` does it, shared by `mocap clean`, `mocap batch` and
/// `mocap clean --manifest`: the pipeline (cleanTake), then one history step per step that ran,
/// so the written take says how it was cleaned (tool, parameters, samples changed, time).
/// Throws as cleanTake (JobCancelled through `job` before any history is written). Cost: cleanTake's.
CleanReport cleanAndRecord(Take& take, const CleanOptions& options, const std::string& tool,
                           const JobControl& job = {});

/// The history steps cleanAndRecord appends, one per step of `options` that ran (stabilize head,
/// repair spikes, fill gaps, smooth) with its parameters, `report`'s sample counts, the whole
/// take's frames, processingTime() and `tool`; for callers that run a step on a selection
/// (mocap.fill_gaps with markers or frames) and narrow the step afterwards. O(#steps).
void recordCleanSteps(Take& take, const CleanOptions& options, const CleanReport& report, const std::string& tool);

/// Writes the cleaned take atomically in the format `output`'s extension names. A BVH of a
/// stabilized take carries the head motion in its root joint, so its markers go in head space.
/// Throws as writeTake / writeBvh. O(take size).
void writeCleanedTake(Take& take, const CleanReport& report, const CleanOptions& options,
                      const std::filesystem::path& output);

/// The time history steps record, UTC ISO 8601: SOURCE_DATE_EPOCH (seconds since 1970, the
/// reproducible-builds convention) when that is set and valid, so reruns write identical files;
/// else the current time. O(1).
[[nodiscard]] std::string processingTime();

} // namespace mocap
