#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/io/take_io.h"

#include <filesystem>
#include <optional>
#include <iostream>

namespace mocap::cli {

int runConvert(const std::vector<std::string>& args)
{
  const Arguments arguments(args, {}, {"--units"});
  arguments.expectPositionals(2, "IN and OUT");
  const std::string& input = arguments.positionals()[0];
  const std::string& output = arguments.positionals()[1];
  (void)formatFromPath(output);  // reject an unknown output type before the read
  std::error_code ec;
  if (std::filesystem::exists(output, ec) && std::filesystem::equivalent(input, output, ec))
    throw UsageError("IN and OUT are the same file; write to a new file");
  std::optional<LengthUnit> units;
  if (const auto text = arguments.value("--units")) {
    units = parseLengthUnit(*text);
    if (!units)
      throw UsageError("--units must be mm, cm or m, not '" + *text + "'");
  }
  std::vector<std::string> warnings;
  Take take = readTake(input, &warnings);
  if (units)
    take.convertUnits(*units);
  for (const auto& w : warnings)
    std::cerr << input << ": warning: " << w << '\n';
  writeTake(take, output);
  return kExitOk;
}

} // namespace mocap::cli
