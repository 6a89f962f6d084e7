#include "views/redraw_memory.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace mocap::ui {

void keepRedrawMemoryMapped()
{
#if defined(__GLIBC__)
  constexpr int kLargestHeapBlock = 32 << 20;  // glibc's ceiling for the mmap threshold on 64-bit
  constexpr int kKeptFreeTop = 256 << 20;
  mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock);
  mallopt(M_TRIM_THRESHOLD, kKeptFreeTop);
#endif
}

} // namespace mocap::ui
