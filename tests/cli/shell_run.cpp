#include "shell_run.h"

#include "mocap/base/file_io.h"

#include <array>
#include <cstdio>
#include <sys/wait.h>

namespace mocap::test {

std::string shellQuote(const std::string& text)
{
  std::string quoted = "'";
  for (const char c : text)
    quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string shellQuote(const std::filesystem::path& path)
{
  return shellQuote(path.string());
}

ShellResult runShell(const std::string& command, const std::filesystem::path& scratch)
{
  const std::filesystem::path errFile = scratch / "shell-stderr.txt";
  const std::string full = "{ " + command + "\n} 2>" + shellQuote(errFile);
  ShellResult result;
  FILE* pipe = popen(full.c_str(), "r");
  if (pipe == nullptr)
    return result;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::error_code ignored;
  if (std::filesystem::exists(errFile, ignored)) {
    result.err = readFileBytes(errFile);
    std::filesystem::remove(errFile, ignored);
  }
  return result;
}

} // namespace mocap::test
