#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

namespace mocap {

/// std::thread::hardware_concurrency(), at least 1.
[[nodiscard]] int hardwareThreads();

/// Runs body(i) for every i in [0, count) on `threads` threads (≤ 0: hardwareThreads()), the
/// caller being one of them and calling tick() between its items. Indices are handed out in
/// order; results must be stored by index so they do not depend on the thread count. Stops
/// handing out work once `cancel` (may be null) is set and returns false then. The first
/// exception a body throws is rethrown here after every thread has stopped.
bool parallelFor(std::size_t count, int threads, const std::function<void(std::size_t)>& body,
                 const std::atomic<bool>* cancel = nullptr, const std::function<void()>& tick = {});

} // namespace mocap
