#include "renderer/huge_page_allocator.h"

#include <sys/mman.h>

#include <mutex>
#include <utility>
#include <vector>

namespace raylab::huge_pages {

namespace {

struct Parking {
    std::mutex mutex;
    int scopes = 0;
    std::vector<std::pair<void*, size_t>> parked;  // (mapping, size)
    size_t bytes = 0;

    void releaseAll() {  // with the mutex held
        for (const auto& [p, size] : parked) munmap(p, size);
        parked.clear();
        bytes = 0;
    }
};

Parking& parking() {
    static Parking* p = new Parking;  // never destroyed: buffers may be freed during exit
    return *p;
}

void* mapFresh(size_t size) {
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

}  // namespace

void* mapAligned(size_t size, bool& fresh) {
    Parking& k = parking();
    {
        std::lock_guard<std::mutex> lock(k.mutex);
        for (size_t i = 0; i < k.parked.size(); ++i) {
            if (k.parked[i].second != size) continue;
            void* p = k.parked[i].first;
            k.parked.erase(k.parked.begin() + std::ptrdiff_t(i));
            k.bytes -= size;
            fresh = false;
            return p;
        }
        // A request of another size: the frames have changed, and what the
        // previous one left may never be asked for again.
        k.releaseAll();
    }
    fresh = true;
    return mapFresh(size);
}

void unmapAligned(void* p, size_t size) {
    Parking& k = parking();
    {
        std::lock_guard<std::mutex> lock(k.mutex);
        if (k.scopes > 0) {
            k.parked.emplace_back(p, size);
            k.bytes += size;
            return;
        }
    }
    munmap(p, size);
}

ReuseScope::ReuseScope() {
    Parking& k = parking();
    std::lock_guard<std::mutex> lock(k.mutex);
    ++k.scopes;
}

ReuseScope::~ReuseScope() {
    Parking& k = parking();
    std::lock_guard<std::mutex> lock(k.mutex);
    if (--k.scopes == 0) k.releaseAll();
}

size_t parkedBytes() {
    Parking& k = parking();
    std::lock_guard<std::mutex> lock(k.mutex);
    return k.bytes;
}

}  // namespace raylab::huge_pages
