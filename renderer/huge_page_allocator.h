#pragma once
// An allocator for the frame's large buffers (film planes, SPD corner grid,
// EXR conversion planes) that backs them with transparent huge pages.
//
// Why: every 4 KiB page of a fresh buffer costs a page fault on first touch,
// and in this project's VMs a fault costs ~9 µs (paravirtual MMU): the 42 MB
// of a 512x512 SPD frame were ~10,700 faults, more wall time than tracing
// tetra.nff. Linux hands out 2 MiB pages only to memory that asks for them
// (transparent_hugepage=madvise, the Debian default): a 2 MiB-aligned mapping
// with madvise(MADV_HUGEPAGE) takes ~25 faults instead (measured: 42 MB first
// touched in 14-20 ms instead of 590-780 ms, load average 15). Where the
// kernel has no huge page at hand it falls back to small pages: the hint can
// only help. Small requests go to operator new as usual.

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <new>

namespace raylab {

namespace huge_pages {

constexpr size_t kHugePage = size_t(2) << 20;
/// Below this a buffer is left to malloc: a huge page would be mostly empty.
/// Half a huge page: one fault for a 1-2 MiB buffer (a 512x512 film's Z,
/// distance and objectId planes) instead of 256-512 small ones, which cost
/// ~10-13 us each here (docs/benchmarks.md, bar 3).
constexpr size_t kThreshold = kHugePage / 2;

inline size_t roundUp(size_t bytes) { return (bytes + kHugePage - 1) & ~(kHugePage - 1); }

inline void* allocate(size_t bytes) {
    if (bytes < kThreshold) return ::operator new(bytes);
    const size_t size = roundUp(bytes);
    // Over-allocate by one huge page, then cut the mapping down to the
    // 2 MiB-aligned part: only aligned 2 MiB ranges can become huge pages.
    const size_t mapped = size + kHugePage;
    void* raw = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) throw std::bad_alloc();
    const uintptr_t start = reinterpret_cast<uintptr_t>(raw);
    const uintptr_t aligned = (start + kHugePage - 1) & ~uintptr_t(kHugePage - 1);
    if (aligned > start) munmap(raw, aligned - start);
    const uintptr_t end = start + mapped, alignedEnd = aligned + size;
    if (end > alignedEnd) munmap(reinterpret_cast<void*>(alignedEnd), end - alignedEnd);
    void* p = reinterpret_cast<void*>(aligned);
    madvise(p, size, MADV_HUGEPAGE);  // a hint: failure only means small pages
    return p;
}

inline void deallocate(void* p, size_t bytes) {
    if (!p) return;
    if (bytes < kThreshold)
        ::operator delete(p);
    else
        munmap(p, roundUp(bytes));
}

}  // namespace huge_pages

/// Standard allocator interface over huge_pages::allocate (stateless: any two
/// instances are interchangeable, so containers move and swap freely).
template <class T>
struct HugePageAllocator {
    using value_type = T;
    HugePageAllocator() = default;
    template <class U>
    HugePageAllocator(const HugePageAllocator<U>&) {}
    T* allocate(size_t n) {
        if (n > size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
        return static_cast<T*>(huge_pages::allocate(n * sizeof(T)));
    }
    void deallocate(T* p, size_t n) { huge_pages::deallocate(p, n * sizeof(T)); }
    template <class U>
    bool operator==(const HugePageAllocator<U>&) const { return true; }
    template <class U>
    bool operator!=(const HugePageAllocator<U>&) const { return false; }
};

}  // namespace raylab
