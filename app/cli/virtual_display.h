#pragma once

#include <string>
#include <vector>

namespace mocap::cli {

/// Runs `argv` (a program and its arguments) on an X server of its own: Xvfb started with
/// `-displayfd`, so it picks a free display itself (two starts never race for one as with
/// `xvfb-run -a`, whose loser connects to the other's server with the wrong cookie and aborts), in
/// a session of its own, so Ctrl+C at the terminal reaches the program (which stops cleanly) but not
/// its X server; Xvfb also ends if this process dies (PR_SET_PDEATHSIG). SIGINT and SIGTERM sent to
/// this process are passed on to the program. Returns the program's exit code (128 + signal if a
/// signal ended it); throws IoError when Xvfb is missing or does not start within 20 s. Blocks
/// until the program ends.
[[nodiscard]] int runOnVirtualDisplay(const std::vector<std::string>& argv, const std::string& screen);

} // namespace mocap::cli
