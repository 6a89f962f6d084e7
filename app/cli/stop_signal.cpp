#include "stop_signal.h"

#include <csignal>

namespace mocap::cli {

namespace {

std::atomic<bool> g_stop{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the flag is set from a signal handler");

// Every signal only sets the flag: ending the process at once could leave an atomic write's
// temporary file behind, and the takes in progress take well under a second each.
void onStopSignal(int /*signal*/)
{
  g_stop.store(true);
}

} // namespace

const std::atomic<bool>& installStopSignals()
{
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  return g_stop;
}

} // namespace mocap::cli
