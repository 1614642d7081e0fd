// useHugePageHeap (apps/heap_pages.h): after it, the main thread's heap has a
// huge-page-advised stretch of at least 60 MiB, and a 1 MiB block comes from
// the heap (not a fresh mapping) and lands in that stretch. Under a sanitizer
// malloc is not glibc's and the call changes nothing: the test says so.

#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

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
    std::free(static_cast<void*>(block));
}
