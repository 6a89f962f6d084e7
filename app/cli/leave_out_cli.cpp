#include "leave_out_cli.h"

#include "arguments.h"

namespace mocap::cli {

void addLeaveOutOptions(CLI::App& command, LeaveOutOptions& options)
{
  numberIn(command.add_option("--leave-out", options.fraction,
                              "share of markers hidden to measure the error; 0: no measurement")
               ->type_name("FRACTION"),
           0.0, 0.9)
      ->capture_default_str();
  wholeNumberIn(command.add_option("--seed", options.seed, "which markers are left out")->type_name("S"), 0,
                1LL << 62)
      ->capture_default_str();
}

void writeLeaveOutJson(JsonWriter& json, const LeaveOutResult& quality, const LeaveOutOptions& options,
                       const std::vector<std::string>& labels)
{
  json.key("leave_out").beginObject();
  json.key("fraction").value(options.fraction);
  json.key("seed").value(static_cast<std::int64_t>(options.seed));
  json.key("hidden").beginArray();
  for (const Eigen::Index h : quality.hidden)
    json.value(labels[static_cast<std::size_t>(h)]);
  json.endArray();
  json.key("samples").value(static_cast<std::int64_t>(quality.samples));
  json.key("rms_mm").value(quality.rmsError);
  json.key("max_mm").value(quality.maxError);
  json.key("rest_error_mm").value(quality.restError);
  json.endObject();
}

} // namespace mocap::cli
