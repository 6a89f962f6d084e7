#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/take_io.h"

#include <filesystem>
#include <iostream>

namespace mocap::cli {

int runConvert(const std::vector<std::string>& args)
{
  const Arguments arguments(args, {});
  arguments.expectPositionals(2, "IN and OUT");
  const std::string& input = arguments.positionals()[0];
  const std::string& output = arguments.positionals()[1];
  (void)formatFromPath(output);  // reject an unknown output type before the read
  std::error_code ec;
  if (std::filesystem::exists(output, ec) && std::filesystem::equivalent(input, output, ec))
    throw UsageError("IN and OUT are the same file; write to a new file");
  std::vector<std::string> warnings;
  const Take take = readTake(input, &warnings);
  for (const auto& w : warnings)
    std::cerr << input << ": warning: " << w << '\n';
  writeTake(take, output);
  return kExitOk;
}

} // namespace mocap::cli
