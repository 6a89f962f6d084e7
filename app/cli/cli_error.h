#pragma once

#include <stdexcept>
#include <string>

namespace mocap::cli {

/// Wrong command-line usage: `mocap` prints the message and the usage line, and exits with 2.
class UsageError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Exit codes of every `mocap` command.
enum ExitCode : int
{
  kExitOk = 0,
  kExitBadInput = 1,
  kExitBadUsage = 2,
  kExitQuality = 3,        ///< every take processed, some below `batch --min-valid` / `clean --min-valid-after`
  kExitInterrupted = 130,  ///< stopped by SIGINT/SIGTERM (128 + SIGINT, the shells' convention)
};

} // namespace mocap::cli
