#include "apps/heap_pages.h"

#include <malloc.h>
#include <unistd.h>

#include <tbb/task_scheduler_observer.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <new>

#include "renderer/huge_pages.h"

namespace raylab {

namespace {

constexpr uintptr_t kHuge = uintptr_t(2) << 20;
/// glibc's chunk header (prev_size, size) sits just below the pointer malloc returns.
constexpr uintptr_t kChunkHeader = 2 * sizeof(size_t);

/// The heads reserved so far: kept reachable, so that a leak checker does
/// not report them (they are never freed on purpose).
std::array<void* volatile, 64> g_heads{};
std::atomic<size_t> g_headCount{0};

/// The first 2 MiB boundary at least `room` bytes above a free top that
/// begins at `from`.
uintptr_t boundaryAbove(uintptr_t from, uintptr_t room) {
    return (from + room + kHuge - 1) & ~(kHuge - 1);
}

/// Reserves [from, to) of the calling thread's arena, `from` being where its
/// free top begins, with a block nobody touches, so that the arena's next
/// allocations start at `to`. False if malloc did not carve it from the top
/// (a sanitizer's malloc): nothing is reserved then.
bool reserveUpTo(uintptr_t from, uintptr_t to) {
    // A request of n bytes takes a chunk of n + sizeof(size_t) rounded up to
    // 16: this one spans [from, to). Its header is written at `from`, the
    // new top's at `to`.
    void* head = std::malloc(to - from - sizeof(size_t));
    if (head != reinterpret_cast<void*>(from + kChunkHeader)) {
        std::free(head);
        return false;
    }
    const size_t i = g_headCount.fetch_add(1);
    if (i < g_heads.size()) g_heads[i] = head;  // beyond: still reserved, just not listed
    return true;
}

/// The whole 2 MiB pages of [first, end) advised (adviseHugePages: regions
/// of 4 MiB and more; the heaps here are 16 and 64 MiB).
void adviseHuge(uintptr_t first, uintptr_t end) {
    if (end > first) adviseHugePages(reinterpret_cast<const void*>(first), end - first);
}

/// Grows the calling thread's (non-main) arena by `bytes`, advises it and
/// reserves its head: a block that large comes from the arena's top, which
/// glibc extends for it; freed, it merges back into the top (the trim
/// threshold, 128 MiB, keeps the top mapped). The only page it touches past
/// the head holds the header after it, at the end of the advised range.
void growWorkerArena(size_t bytes) {
    void* volatile block = std::malloc(bytes);
    if (!block) return;
    const auto at = reinterpret_cast<uintptr_t>(static_cast<void*>(block));
    std::free(static_cast<void*>(block));
    const uintptr_t from = at - kChunkHeader;
    const uintptr_t first = boundaryAbove(from, 2 * kChunkHeader);
    if (at + bytes < first + kHuge) return;  // not even one whole 2 MiB page
    adviseHuge(first, at + bytes);
    (void)reserveUpTo(from, first);  // after the advice: it writes the top's header at `first`
}

}  // namespace

void useHugePageHeap() {
    // The heap grows at once by the block and the pad (less the free top it
    // had, ~0.1-0.2 MiB): 64 MiB of address space, then advised.
    constexpr size_t kGrow = size_t(30) << 20;  // below the mmap threshold
    constexpr size_t kPad = size_t(36) << 20;
    // Fixed thresholds (setting them also stops glibc's dynamic threshold).
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 128 << 20);
    // The heap's free top is its last chunk, [sbrk(0) - keepcost, sbrk(0)).
    // Its head up to 4 KiB below the first 2 MiB boundary is reserved first:
    // nothing may touch the boundary's page before the advice.
    const auto end = reinterpret_cast<uintptr_t>(sbrk(0));
    const uintptr_t from = end - mallinfo2().keepcost;
    uintptr_t first = boundaryAbove(from, 2 * kChunkHeader + 4096);
    if (!reserveUpTo(from, first - 4096)) first = boundaryAbove(end, 0);
    // A block larger than the heap's free top makes malloc grow it by the
    // pad (volatile: the compiler may not drop the malloc/free pair); freed,
    // it stays in the heap's top (below the trim threshold). malloc writes
    // the header after it before the advice: that 2 MiB page, 30 MiB up,
    // stays on small pages.
    mallopt(M_TOP_PAD, int(kPad));
    void* volatile grow = std::malloc(kGrow);
    std::free(static_cast<void*>(grow));
    mallopt(M_TOP_PAD, 128 << 10);  // glibc's default for later growth
    adviseHuge(first, reinterpret_cast<uintptr_t>(sbrk(0)));
}

namespace {

/// Each worker's first entry into the observed arena grows its malloc arena
/// (16 MiB of address space: gears' worker uses ~3 MB; beyond it the arena
/// grows by small pages as before).
struct WorkerArenaObserver : tbb::task_scheduler_observer {
    void on_scheduler_entry(bool worker) override {
        thread_local bool done = false;
        if (!worker || done) return;
        done = true;
        growWorkerArena(size_t(16) << 20);
    }
};

/// Never destroyed: observing stops with the process. (observe(false) leaves
/// oneTBB's record of the observer to be freed by threads that may not run
/// again, a leak at exit; and after a failed observe(true), destroying the
/// observer crashes.)
std::atomic<WorkerArenaObserver*> g_workerObserver{nullptr};

}  // namespace

void useHugePageWorkerHeaps() {
    if (g_workerObserver.load()) return;
    auto* observer = new (std::nothrow) WorkerArenaObserver;
    if (!observer) return;
    WorkerArenaObserver* none = nullptr;
    if (!g_workerObserver.compare_exchange_strong(none, observer)) {
        delete observer;  // another thread was first
        return;
    }
    // observe(true) starts TBB's scheduler, which can fail for memory (under
    // ulimit -v): the render then reports the shortage where it first needs
    // TBB.
    try {
        observer->observe(true);
    } catch (const std::exception&) {
    }
}

}  // namespace raylab
