// `mocap fix-swaps IN -o OUT [--report FILE.json] [--jump-factor F] [--json]`: finds frames where two
// labels exchange and repairs them (core/include/mocap/tracking/swap_detection.h); the report lists each
// swap for review.
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/base/file_io.h"
#include "mocap/base/json_writer.h"
#include "mocap/tracking/swap_detection.h"
#include "mocap/io/take_io.h"

#include <iostream>

namespace mocap::cli {

namespace {

std::string reportJson(const std::string& input, const std::string& output, const Take& take,
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

} // namespace

int runFixSwaps(const std::vector<std::string>& args)
{
  const Arguments arguments(args, {"--json"}, {"-o", "--output", "--report", "--jump-factor"});
  const auto [input, output] = arguments.inputAndOutput();
  SwapOptions options;
  if (const auto factor = arguments.number("--jump-factor", 2.0, 1000.0))
    options.jumpFactor = *factor;
  std::vector<std::string> warnings;
  Take take = readTake(input, &warnings);
  for (const auto& w : warnings)
    std::cerr << input << ": warning: " << w << '\n';
  const std::vector<LabelSwap> swaps = repairSwaps(take, options);
  writeTake(take, output);
  const std::string report = reportJson(input, output, take, swaps);
  if (const auto reportFile = arguments.value("--report"))
    writeFileAtomically(*reportFile, report);
  if (arguments.has("--json")) {
    std::cout << report;
  } else {
    std::cout << output << ": " << swaps.size() << " label swaps repaired\n";
    for (const LabelSwap& swap : swaps)
      std::cout << "  frame " << take.firstFrame() + swap.frame << ": " << take.label(swap.first) << " <-> "
                << take.label(swap.second) << '\n';
  }
  return kExitOk;
}

} // namespace mocap::cli
