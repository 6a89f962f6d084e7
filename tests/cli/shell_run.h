#pragma once

#include <filesystem>
#include <string>

namespace mocap::test {

/// What a shell command did.
struct ShellResult
{
  int exitCode = -1;  ///< -1 when it did not exit normally (a signal)
  std::string out, err;
};

/// `text` in single quotes for sh.
[[nodiscard]] std::string shellQuote(const std::string& text);
[[nodiscard]] std::string shellQuote(const std::filesystem::path& path);

/// Runs `command` with sh, its stdout and stderr captured (stderr through a file in `scratch`).
[[nodiscard]] ShellResult runShell(const std::string& command, const std::filesystem::path& scratch);

} // namespace mocap::test
