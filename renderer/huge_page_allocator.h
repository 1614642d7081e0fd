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

/// A 2 MiB-aligned mapping of `size` bytes (a multiple of kHugePage) with the
/// huge-page hint (huge_page_allocator.cpp). `fresh` tells whether its pages
/// are new (all zero) or a parked mapping taken back (any content).
void* mapAligned(size_t size, bool& fresh);
/// Unmaps a mapAligned mapping, or parks it while a ReuseScope is open.
void unmapAligned(void* p, size_t size);

/// `fresh`, when given, is set to whether the memory is known to be zero.
inline void* allocate(size_t bytes, bool* fresh = nullptr) {
    if (bytes < kThreshold) {
        if (fresh) *fresh = false;
        return ::operator new(bytes);
    }
    bool zero = false;
    void* p = mapAligned(roundUp(bytes), zero);
    if (fresh) *fresh = zero;
    return p;
}

inline void deallocate(void* p, size_t bytes) {
    if (!p) return;
    if (bytes < kThreshold)
        ::operator delete(p);
    else
        unmapAligned(p, roundUp(bytes));
}

/// While one is alive, a freed large buffer is parked instead of unmapped,
/// and the next request of the same size takes it back. For a process that
/// renders again and again (`raylab bench`, `render --frames`): each frame
/// asks for the same buffers, and fresh pages cost a fault and the kernel's
/// zeroing each (here ~1.6 ms per MB when the host has to supply the
/// memory: docs/benchmarks.md, bar 2). A request no parked mapping fits
/// releases them all first, so parked memory is only ever what the previous
/// frame had; the last scope to close releases the rest. Scopes nest; any
/// thread may allocate and free inside one.
class ReuseScope {
public:
    ReuseScope();
    ~ReuseScope();
    ReuseScope(const ReuseScope&) = delete;
    ReuseScope& operator=(const ReuseScope&) = delete;
};

/// Bytes parked now (for tests and statistics).
size_t parkedBytes();

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
