#include "mocap/model/sample_buffer.h"

#include <cstdlib>
#include <fstream>
#include <mutex>
#include <new>
#include <string>
#include <unordered_map>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace mocap {

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kHugeThreshold = std::size_t{4} << 20;
} // namespace

namespace {

/// Large blocks freed recently, kept for the next take of similar size: a fresh block costs a
/// kernel page clear per page, which is more than decoding a C3D file into it. At most
/// kRetainedBytes stay cached; anything else goes back to the system.
class LargeBlockCache
{
public:
  void* take(std::size_t bytes)
  {
    std::lock_guard lock(m_mutex);
    for (std::size_t i = 0; i < m_free.size(); ++i) {
      if (m_free[i].bytes >= bytes && m_free[i].bytes <= 2 * bytes) {
        void* data = m_free[i].data;
        m_retained -= m_free[i].bytes;
        m_sizes[data] = m_free[i].bytes;
        m_free.erase(m_free.begin() + static_cast<std::ptrdiff_t>(i));
        return data;
      }
    }
    return nullptr;
  }

  void remember(void* data, std::size_t bytes)
  {
    std::lock_guard lock(m_mutex);
    m_sizes[data] = bytes;
  }

  /// True when `data` is a large block (now cached or released); false for small blocks.
  bool give(void* data)
  {
    std::lock_guard lock(m_mutex);
    const auto it = m_sizes.find(data);
    if (it == m_sizes.end())
      return false;
    const std::size_t bytes = it->second;
    m_sizes.erase(it);
    while (!m_free.empty() && m_retained + bytes > kRetainedBytes) {
      std::free(m_free.front().data);
      m_retained -= m_free.front().bytes;
      m_free.erase(m_free.begin());
    }
    if (bytes <= kRetainedBytes) {
      m_free.push_back({data, bytes});
      m_retained += bytes;
    } else {
      std::free(data);
    }
    return true;
  }

private:
  static constexpr std::size_t kRetainedBytes = std::size_t{256} << 20;
  struct Block
  {
    void* data;
    std::size_t bytes;
  };
  std::mutex m_mutex;
  std::vector<Block> m_free;                       // oldest first
  std::unordered_map<void*, std::size_t> m_sizes;  // large blocks handed out
  std::size_t m_retained = 0;
};

#if defined(__linux__) && defined(MADV_HUGEPAGE)
/// Whether asking for transparent huge pages cannot stall: only when the kernel's THP `defrag`
/// policy is `defer` or `never`. Under `madvise` (the common default), `defer+madvise` and
/// `always`, a fault in a MADV_HUGEPAGE region reclaims and compacts memory synchronously when no
/// free 2 MB block is at hand. Measured with `mocap info` on the 19 MB benchmark C3D, 100 runs on
/// a machine whose free memory was fragmented (15 GB held in split huge pages): with huge pages
/// 1.1 direct compactions per run, p99 94 ms, max 164 ms; with 4 KB pages none, p99 = max 78 ms
/// (a 60 s run was once seen with huge pages). The price of 4 KB pages is their faults: median
/// 32 → 73 ms per run on an unfragmented, loaded machine. Read once. O(1).
bool hugePagesWithoutStalls()
{
  static const bool safe = [] {
    std::ifstream file("/sys/kernel/mm/transparent_hugepage/defrag");
    std::string policies;
    std::getline(file, policies);
    return policies.find("[defer]") != std::string::npos || policies.find("[never]") != std::string::npos;
  }();
  return safe;
}

/// Maps the 4 KB pages of a fresh block's first `bytes` in one call (MADV_POPULATE_WRITE, Linux
/// 5.14) instead of one page fault each as the reader first writes them: the block is written
/// whole anyway, and a fault costs more than the page's clearing. `mocap info` on the 19 MB
/// benchmark C3D: 10 804 → 1 427 page faults, 69 → 52 ms (means of 100 runs, one machine). A
/// kernel without it refuses the call, which only costs the faults. O(bytes).
void populateForWriting(void* block, std::size_t bytes)
{
#ifndef MADV_POPULATE_WRITE
  constexpr int MADV_POPULATE_WRITE = 23;
#endif
  const std::size_t page = 4096;
  madvise(block, (bytes + page - 1) / page * page, MADV_POPULATE_WRITE);
}
#endif

LargeBlockCache& largeBlocks()
{
  static LargeBlockCache* cache = new LargeBlockCache;  // never destroyed: buffers may outlive statics
  return *cache;
}

} // namespace

void* allocateSamples(std::size_t bytes)
{
  if (bytes == 0)
    return nullptr;
  if (bytes < kHugeThreshold) {
    void* small = std::malloc(bytes);
    if (!small)
      throw std::bad_alloc();
    return small;
  }
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  if (void* reused = largeBlocks().take(rounded))
    return reused;
  void* large = std::aligned_alloc(kHugePage, rounded);
  if (!large)
    throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (hugePagesWithoutStalls())
    madvise(large, rounded, MADV_HUGEPAGE);  // a hint: failure only costs speed
  else
    populateForWriting(large, bytes);
#endif
  largeBlocks().remember(large, rounded);
  return large;
}

void freeSamples(void* data) noexcept
{
  if (data && !largeBlocks().give(data))
    std::free(data);
}

} // namespace mocap
