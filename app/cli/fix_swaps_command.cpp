// `mocap fix-swaps IN -o OUT [--report FILE.json] [--jump-factor F] [--json]`: finds frames where two
// labels exchange and repairs them (core/include/mocap/tracking/swap_detection.h); the report lists each
// swap for review.
#include "take_input.h"
#include "take_output.h"
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/base/file_io.h"
#include "mocap/base/json_writer.h"
#include "mocap/tracking/swap_detection.h"
#include "mocap/io/take_io.h"

#include <iostream>
#include <memory>
#include <optional>

namespace mocap::cli {

namespace {

std::string swapReportJson(const std::string& input, const std::string& output, const Take& take,
                           const std::vector<LabelSwap>& swaps)
{
  JsonWriter json;
  json.beginObject();
  json.key("input").value(input);
  json.key("output").value(output);
  json.key("count").value(static_cast<std::int64_t>(swaps.size()));
  json.key("swaps").beginArray();
  for (const LabelSwap& swap : swaps) {
    json.beginObject();
    json.key("frame").value(take.firstFrame() + swap.frame);
    json.key("first").value(take.label(swap.first));
    json.key("second").value(take.label(swap.second));
    json.key("jump").value(swap.jump);
    json.key("explained").value(swap.explained);
    json.endObject();
  }
  json.endArray();
  json.endObject();
  return json.str() + "\n";
}

struct FixSwapsArguments
{
  std::string input, output;
  std::optional<std::string> report;
  SwapOptions options;
  bool json = false;
};

int runFixSwaps(const FixSwapsArguments& arguments)
{
  const std::string& input = arguments.input;
  const std::string& output = arguments.output;
  (void)formatFromPath(output);  // reject an unknown output type before the read
  SwapOptions options = arguments.options;
  Take take = readInputTake(input);
  const std::vector<LabelSwap> swaps = repairSwaps(take, options);
  writeOutputTake(take, output);
  const std::string report = swapReportJson(input, output, take, swaps);
  if (arguments.report)
    writeFileAtomically(*arguments.report, report);
  if (arguments.json) {
    std::cout << report;
  } else {
    std::cout << output << ": " << swaps.size() << " label swaps repaired\n";
    for (const LabelSwap& swap : swaps)
      std::cout << "  frame " << take.firstFrame() + swap.frame << ": " << take.label(swap.first) << " <-> "
                << take.label(swap.second) << '\n';
  }
  return kExitOk;
}

} // namespace

Command addFixSwaps(CLI::App& mocap)
{
  CLI::App* command = mocap.add_subcommand("fix-swaps", "find and repair frames where two labels exchange");
  const auto a = std::make_shared<FixSwapsArguments>();
  command->add_option("IN", a->input, "the labelled take")->required();
  command->add_option("-o,--output", a->output, "the repaired take; its extension names the format")
      ->required()
      ->type_name("OUT");
  command->add_option("--report", a->report, "write every swap found as JSON")->type_name("FILE.json");
  numberIn(command->add_option("--jump-factor", a->options.jumpFactor, "how far a jump must stand out")
               ->type_name("F"),
           2.0, 1000.0)
      ->capture_default_str();
  command->add_flag("--json", a->json, "print the report as JSON");
  return {command, [a] { return runFixSwaps(*a); }};
}

} // namespace mocap::cli
