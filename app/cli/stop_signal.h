#pragma once

#include <atomic>

namespace mocap::cli {

/// Makes SIGINT and SIGTERM set the returned flag instead of ending the process, so a long
/// command (mocap batch) stops handing out work and finishes cleanly: what is done is kept and
/// nothing is left half written (a repeated signal changes nothing). O(1).
[[nodiscard]] const std::atomic<bool>& installStopSignals();

} // namespace mocap::cli
