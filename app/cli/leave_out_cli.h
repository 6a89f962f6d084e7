#pragma once

#include <CLI/CLI.hpp>

#include "mocap/base/json_writer.h"
#include "mocap/evaluation/deformation_evaluation.h"

#include <string>
#include <vector>

namespace mocap::cli {

/// --leave-out FRACTION and --seed S, shared by `mocap deform` and `mocap solve`.
void addLeaveOutOptions(CLI::App& command, LeaveOutOptions& options);

/// The "leave_out" object of `mocap deform --json` and `mocap solve --json`: the share and seed,
/// the hidden markers by label (`labels` in binding order), samples and the errors in mm.
void writeLeaveOutJson(JsonWriter& json, const LeaveOutResult& quality, const LeaveOutOptions& options,
                       const std::vector<std::string>& labels);

} // namespace mocap::cli
