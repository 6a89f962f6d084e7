#include "take_output.h"

#include "mocap/io/take_io.h"

#include <iostream>

namespace mocap::cli {

void noteLeftOut(const Take& take, const std::string& path)
{
  const std::string leftOut = leftOutOnWriting(take, formatFromPath(path));
  if (!leftOut.empty())
    std::cerr << path << ": note: " << leftOut << '\n';
}

void writeOutputTake(const Take& take, const std::string& path)
{
  writeTake(take, path);
  noteLeftOut(take, path);
}

} // namespace mocap::cli
