#pragma once
// One huge-page mapping shared by all of a film's planes.
//
// Why: each plane on a mapping of its own is rounded up to whole 2 MiB pages,
// and the kernel zeroes every page a plane touches: a 512x512 SPD film's
// 21 MB took 26 MB (the 1 MB planes Z, distance and objectId a 2 MiB page
// each, the 3 MB normal and albedo planes 4 MB each). Fresh memory costs
// ~1.2-3 ms per MB on this project's VMs (docs/benchmarks.md), so the 5 MB
// that no pixel used were ~6 ms of one core in every render. Carved out of
// one mapping, the planes lie back to back and only the last page is partly
// empty.
//
// PlaneAllocator is a std::vector allocator that takes its memory from a
// PlaneArena when it has one and from huge_pages::allocate otherwise (the
// default, as HugePageAllocator). The arena lives as long as any allocator
// refers to it; memory taken from it is never given back piecemeal, only
// with the whole arena. A vector moves and swaps its allocator with its
// buffer (propagate_on_container_*), and a copy gets an allocator of its own
// (select_on_container_copy_construction), so a buffer is always returned
// to the allocator that handed it out.

#include <atomic>
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>

#include "renderer/huge_page_allocator.h"

namespace raylab {

/// A block of memory handed out front to back in 64-byte-aligned slots.
class PlaneArena {
public:
    static constexpr size_t kAlignment = 64;
    /// The bytes a request of `bytes` takes from the arena.
    static constexpr size_t slot(size_t bytes) { return (bytes + kAlignment - 1) & ~(kAlignment - 1); }

    /// `bytes`: the sum of slot() of every request it is meant to serve.
    explicit PlaneArena(size_t bytes);
    ~PlaneArena();
    PlaneArena(const PlaneArena&) = delete;
    PlaneArena& operator=(const PlaneArena&) = delete;

    /// `bytes` from the unused rest, or nullptr when they do not fit.
    void* take(size_t bytes);
    bool owns(const void* p) const {
        const auto* b = static_cast<const unsigned char*>(p);
        return b >= m_base && b < m_base + m_size;
    }
    size_t size() const { return m_size; }
    size_t used() const { return m_used.load(std::memory_order_relaxed); }

private:
    unsigned char* m_base = nullptr;
    size_t m_size = 0;
    std::atomic<size_t> m_used{0};
};

template <class T>
class PlaneAllocator {
public:
    using value_type = T;
    using propagate_on_container_move_assignment = std::true_type;
    using propagate_on_container_swap = std::true_type;
    using is_always_equal = std::false_type;

    PlaneAllocator() = default;
    explicit PlaneAllocator(std::shared_ptr<PlaneArena> arena) : m_arena(std::move(arena)) {}
    template <class U>
    PlaneAllocator(const PlaneAllocator<U>& o) : m_arena(o.arena()) {}

    /// A copied container gets memory of its own, not the original's arena.
    PlaneAllocator select_on_container_copy_construction() const { return PlaneAllocator(); }

    T* allocate(size_t n) {
        if (n > size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
        if (m_arena)
            if (void* p = m_arena->take(n * sizeof(T))) return static_cast<T*>(p);
        return static_cast<T*>(huge_pages::allocate(n * sizeof(T)));
    }
    void deallocate(T* p, size_t n) {
        if (m_arena && m_arena->owns(p)) return;  // freed with the arena
        huge_pages::deallocate(p, n * sizeof(T));
    }

    std::shared_ptr<PlaneArena> arena() const { return m_arena; }
    template <class U>
    bool operator==(const PlaneAllocator<U>& o) const { return m_arena == o.arena(); }
    template <class U>
    bool operator!=(const PlaneAllocator<U>& o) const { return !(*this == o); }

private:
    std::shared_ptr<PlaneArena> m_arena;
};

}  // namespace raylab
