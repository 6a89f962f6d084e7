#include "take_input.h"

#include "mocap/io/take_io.h"

#include <iostream>
#include <vector>

namespace mocap::cli {

Take readInputTake(const std::string& path)
{
  std::vector<std::string> warnings;
  Take take = readTake(path, &warnings);
  for (const std::string& warning : warnings)
    std::cerr << path << ": warning: " << warning << '\n';
  return take;
}

} // namespace mocap::cli
