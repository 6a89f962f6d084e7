#pragma once

#include <string>
#include <sys/types.h>
#include <vector>

namespace mocap {

/// One running process as /proc/PID/stat gives it (Linux).
struct ProcessEntry
{
  pid_t pid = 0;
  pid_t parent = 0;
  pid_t group = 0;   ///< process group
  std::string name;  ///< the executable's name, at most 15 characters
};

/// Every process this user can see; empty where /proc is missing. O(#processes).
[[nodiscard]] std::vector<ProcessEntry> runningProcesses();

} // namespace mocap
