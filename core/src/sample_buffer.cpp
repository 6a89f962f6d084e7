#include "mocap/sample_buffer.h"

#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace mocap {

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kHugeThreshold = std::size_t{4} << 20;
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
  void* large = std::aligned_alloc(kHugePage, rounded);
  if (!large)
    throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  madvise(large, rounded, MADV_HUGEPAGE);  // a hint: failure only costs speed
#endif
  return large;
}

void freeSamples(void* data) noexcept
{
  std::free(data);
}

} // namespace mocap
