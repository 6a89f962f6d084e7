#include "mocap/base/process_list.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace mocap {

std::vector<ProcessEntry> runningProcesses()
{
  std::vector<ProcessEntry> found;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator("/proc", error)) {
    const std::string id = entry.path().filename().string();
    if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
      continue;
    // "PID (NAME) STATE PPID PGRP ...": the name may hold spaces and parentheses, so it ends at the last ')'.
    std::ifstream file(entry.path() / "stat");
    std::string stat;
    std::getline(file, stat);
    const std::size_t open = stat.find('('), close = stat.rfind(')');
    if (open == std::string::npos || close == std::string::npos || close < open || close + 2 > stat.size())
      continue;
    std::istringstream rest(stat.substr(close + 2));
    char state = 0;
    long parent = 0, group = 0;
    if (!(rest >> state >> parent >> group))
      continue;
    found.push_back({static_cast<pid_t>(std::stol(id)), static_cast<pid_t>(parent), static_cast<pid_t>(group),
                     stat.substr(open + 1, close - open - 1)});
  }
  return found;
}

} // namespace mocap
