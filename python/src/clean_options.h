#pragma once
// Cleaning options and reports shared by mocap.clean and the single steps (mocap.detect_spikes,
// fill_gaps, smooth, stabilize): options go through the cleaning preset's reader and reports
// through `mocap clean --report`'s writer, so names, defaults, checks and keys are the CLI's.

#include "mocap/cleaning/clean_pipeline.h"

#include <pybind11/pybind11.h>

#include <string>

namespace mocap::python {

/// The tool the history steps of a cleaning from Python name.
inline constexpr const char* kCleanTool = "mocap python";

/// A cleaning preset in JSON (`mocap batch --preset`'s format, a dict of steps) read as
/// parseCleanPreset reads a file; `source` names it in the errors. O(#keys).
[[nodiscard]] CleanOptions parseCleanOptions(const pybind11::dict& preset, const std::string& source);

/// `mocap clean --report`'s JSON of one cleaning, as a dict (input and output empty).
/// O(#spikes + #gaps + #markers).
[[nodiscard]] pybind11::dict cleanReportDict(const Take& take, const CleanOptions& options, const CleanReport& report);

/// Cleans the take in place as `mocap clean` does (cleanAndRecord, the GIL released) and returns
/// the report dict; `progress(fraction)` as PythonJob calls it. Ctrl+C (or a callback's False)
/// stops it at the next checkpoint and leaves the take as it was. Throws as cleanAndRecord.
[[nodiscard]] pybind11::dict cleanAndReport(Take& take, const CleanOptions& options,
                                            const pybind11::object& progress = pybind11::none());

} // namespace mocap::python
