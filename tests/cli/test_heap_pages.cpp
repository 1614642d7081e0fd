// useHugePageHeap (apps/heap_pages.h): after it, the main thread's heap has a
// huge-page-advised stretch of at least 60 MiB, and a 1 MiB block comes from
// the heap (not a fresh mapping) and lies in that stretch from its first
// pages on (the heap's head is reserved). useHugePageWorkerHeaps: a TBB
// worker's blocks lie in an advised stretch of its own arena after it, and
// not without it. Under a sanitizer malloc is not glibc's and the calls
// change nothing: the tests say so.

#include <doctest/doctest.h>

#include <unistd.h>

#include <tbb/task_group.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "apps/heap_pages.h"

using namespace raylab;

namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kGlibcMalloc = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
constexpr bool kGlibcMalloc = false;
#else
constexpr bool kGlibcMalloc = true;
#endif
#else
constexpr bool kGlibcMalloc = true;
#endif

struct Range {
    uintptr_t begin = 0, end = 0;
};

/// The mapping of /proc/self/smaps that holds `address`, and whether its
/// VmFlags have "hg" (MADV_HUGEPAGE).
bool advisedMappingOf(uintptr_t address, Range& range) {
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        uintptr_t b = 0, e = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> b >> dash >> e && dash == '-' && line.find(':') > line.find(' ')) {
            inside = b <= address && address < e;
            if (inside) range = {b, e};
            continue;
        }
        if (inside && line.rfind("VmFlags:", 0) == 0) return line.find(" hg") != std::string::npos;
    }
    return false;
}

}  // namespace

TEST_CASE("heap pages: the heap grows by an advised stretch that serves megabyte blocks") {
    if (!kGlibcMalloc) {
        MESSAGE("sanitizer build: malloc is not glibc's, nothing to check");
        return;
    }
    const auto before = reinterpret_cast<uintptr_t>(sbrk(0));
    useHugePageHeap();
    const auto after = reinterpret_cast<uintptr_t>(sbrk(0));
    REQUIRE(after - before >= (size_t(64) << 20));
    void* volatile block = std::malloc(size_t(1) << 20);
    REQUIRE(block != nullptr);
    const auto at = reinterpret_cast<uintptr_t>(static_cast<void*>(block));
    // From the heap's top (which may start just below the growth), not a
    // mapping of its own far away.
    CHECK(at < after);
    CHECK(at + (size_t(1) << 20) > before);
    std::memset(static_cast<void*>(block), 1, size_t(1) << 20);
    Range range;
    const uintptr_t middle = (before + after) / 2;
    CHECK(advisedMappingOf(middle, range));
    CHECK(range.end - range.begin >= (size_t(60) << 20));
    // The block's first pages too: allocations start above the heap's head
    // (which stays on small pages), 4 KiB below a 2 MiB boundary at most.
    Range first;
    CHECK(advisedMappingOf(at + 4096, first));
    CHECK(first.begin == range.begin);
    std::free(static_cast<void*>(block));
}

namespace {

/// Where a 1 MiB block that a TBB worker allocates lies: whether its page
/// 8 KiB in belongs to a huge-page-advised mapping. Two tasks wait for each
/// other, so one of them runs on a worker; false in `ran` if no worker came
/// within ten seconds.
bool workerBlockAdvised(bool& ran) {
    std::atomic<int> started{0};
    std::atomic<bool> advised{false}, measured{false};
    const auto mainThread = std::this_thread::get_id();
    const auto task = [&] {
        started.fetch_add(1);
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (started.load() < 2 && std::chrono::steady_clock::now() < deadline)
            std::this_thread::yield();
        if (std::this_thread::get_id() == mainThread || started.load() < 2) return;
        void* volatile block = std::malloc(size_t(1) << 20);
        Range range;
        advised = advisedMappingOf(reinterpret_cast<uintptr_t>(static_cast<void*>(block)) + 8192, range);
        measured = true;
        std::free(static_cast<void*>(block));
    };
    tbb::task_group group;
    group.run(task);
    group.run(task);
    group.wait();
    ran = measured;
    return advised;
}

}  // namespace

TEST_CASE("heap pages: TBB workers allocate from advised arenas after useHugePageWorkerHeaps") {
    if (!kGlibcMalloc) {
        MESSAGE("sanitizer build: malloc is not glibc's, nothing to check");
        return;
    }
    if (tbb::this_task_arena::max_concurrency() < 2) {
        MESSAGE("one hardware thread: no TBB worker to look at");
        return;
    }
    useHugePageHeap();
    useHugePageWorkerHeaps();
    bool ran = false;
    const bool advised = workerBlockAdvised(ran);
    REQUIRE(ran);
    CHECK(advised);
}

TEST_CASE("heap pages: without useHugePageWorkerHeaps a TBB worker's arena is not advised") {
    // The control for the test above: the advice comes from the observer.
    if (!kGlibcMalloc || tbb::this_task_arena::max_concurrency() < 2) return;
    useHugePageHeap();
    bool ran = false;
    const bool advised = workerBlockAdvised(ran);
    REQUIRE(ran);
    CHECK_FALSE(advised);
}
