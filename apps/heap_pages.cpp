#include "apps/heap_pages.h"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>

namespace raylab {

void useHugePageHeap() {
    constexpr size_t kHuge = size_t(2) << 20;
    constexpr size_t kPad = size_t(64) << 20;  // heap grown at once, then advised
    // Fixed thresholds (setting them also stops glibc's dynamic threshold).
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 128 << 20);
    mallopt(M_TOP_PAD, int(kPad));
    const auto before = reinterpret_cast<uintptr_t>(sbrk(0));
    // A block larger than the heap's free top makes malloc grow it by the pad
    // (volatile: the compiler may not drop the malloc/free pair).
    void* volatile grow = std::malloc(kHuge);
    std::free(grow);  // stays in the heap (below the trim threshold)
    const auto after = reinterpret_cast<uintptr_t>(sbrk(0));
    mallopt(M_TOP_PAD, 128 << 10);  // glibc's default for later growth
    const uintptr_t begin = (before + kHuge - 1) & ~uintptr_t(kHuge - 1);
    const uintptr_t end = after & ~uintptr_t(kHuge - 1);
    if (end > begin)
        (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice only
}

}  // namespace raylab
