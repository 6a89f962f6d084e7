#include "mocap/base/parallel_for.h"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace mocap {

int hardwareThreads()
{
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

bool parallelFor(std::size_t count, int threads, const std::function<void(std::size_t)>& body,
                 const std::atomic<bool>* cancel, const std::function<void()>& tick)
{
  const auto cancelled = [cancel] { return cancel != nullptr && cancel->load(std::memory_order_relaxed); };
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::exception_ptr failure;
  std::mutex failureMutex;
  const auto work = [&](bool caller) {
    while (!stop.load(std::memory_order_relaxed)) {
      if (cancelled()) {
        stop = true;
        break;
      }
      const std::size_t i = next.fetch_add(1, std::memory_order_relaxed);
      if (i >= count)
        break;
      try {
        body(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failureMutex);
        if (!failure)
          failure = std::current_exception();
        stop = true;
      }
      if (caller && tick)
        tick();
    }
  };
  if (threads <= 0)
    threads = hardwareThreads();
  std::vector<std::thread> pool;
  const auto extra = static_cast<std::size_t>(threads - 1);
  for (std::size_t t = 0; t < std::min(extra, count > 0 ? count - 1 : 0); ++t)
    pool.emplace_back(work, false);
  work(true);
  for (auto& thread : pool)
    thread.join();
  if (failure)
    std::rethrow_exception(failure);
  return !cancelled();
}

} // namespace mocap
