// The frame buffers' allocator: small requests through operator new, large
// ones as 2 MiB-aligned mappings with the huge-page hint; containers behave
// as with std::allocator. HugeArray: zero-filled fixed arrays on the same mappings.

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "renderer/huge_array.h"
#include "renderer/huge_page_allocator.h"

using namespace raylab;

TEST_CASE("huge page allocator: sizes around the threshold, alignment, contents") {
    HugePageAllocator<float> a;
    for (size_t bytes : {size_t(4), size_t(4096), huge_pages::kThreshold - 4,
                         huge_pages::kThreshold, huge_pages::kThreshold + 4, size_t(13) << 20}) {
        CAPTURE(bytes);
        const size_t n = bytes / sizeof(float);
        float* p = a.allocate(n);
        REQUIRE(p != nullptr);
        if (bytes >= huge_pages::kThreshold)
            CHECK(reinterpret_cast<uintptr_t>(p) % huge_pages::kHugePage == 0);
        for (size_t i = 0; i < n; ++i) p[i] = float(i);  // every byte is writable
        CHECK(p[n - 1] == float(n - 1));
        a.deallocate(p, n);
    }
}

TEST_CASE("huge page allocator: a vector grows across the threshold and keeps its values") {
    std::vector<uint32_t, HugePageAllocator<uint32_t>> v;
    for (uint32_t i = 0; i < (3u << 20); ++i) v.push_back(i);  // 12 MiB, several reallocations
    CHECK(std::accumulate(v.begin(), v.end(), uint64_t(0)) == uint64_t(3u << 20) * ((3u << 20) - 1) / 2);
    auto moved = std::move(v);
    CHECK(moved.size() == (3u << 20));
    CHECK(moved.back() == (3u << 20) - 1);
    moved.assign(10, 7u);  // back below the threshold
    CHECK(moved == std::vector<uint32_t, HugePageAllocator<uint32_t>>(10, 7u));
}

TEST_CASE("HugeArray: zero bytes at any size, 2 MiB-aligned when large, moves and frees") {
    for (size_t n : {size_t(1), size_t(1000), (huge_pages::kThreshold / 8) - 1,
                     huge_pages::kThreshold / 8, size_t(3) << 20}) {
        CAPTURE(n);
        HugeArray<uint64_t> a(n);
        REQUIRE(a.size() == n);
        if (n * 8 >= huge_pages::kThreshold)
            CHECK(reinterpret_cast<uintptr_t>(a.data()) % huge_pages::kHugePage == 0);
        uint64_t nonZero = 0;
        for (size_t i = 0; i < n; ++i) nonZero += a[i] != 0;
        CHECK(nonZero == 0);
        a[n - 1] = 42;
        HugeArray<uint64_t> b(std::move(a));
        CHECK(a.empty());
        CHECK(b.size() == n);
        CHECK(b[n - 1] == 42);
        b.release();
        CHECK(b.empty());
        CHECK(b.data() == nullptr);
    }
    HugeArray<double> none(0);
    CHECK(none.empty());
}

TEST_CASE("ReuseScope: a freed mapping serves the next request of its size, zeroed for a HugeArray") {
    const size_t bytes = size_t(3) << 20;  // rounds to two huge pages
    const size_t n = bytes / sizeof(uint64_t);
    REQUIRE(huge_pages::parkedBytes() == 0);
    {
        // Without a scope a freed mapping is unmapped at once.
        HugeArray<uint64_t> a(n);
        a.release();
        CHECK(huge_pages::parkedBytes() == 0);
    }
    {
        const huge_pages::ReuseScope scope;
        HugeArray<uint64_t> a(n);
        const uint64_t* first = a.data();
        for (size_t i = 0; i < n; ++i) a[i] = i + 1;  // leave every byte non-zero
        a.release();
        CHECK(huge_pages::parkedBytes() == huge_pages::roundUp(bytes));

        // The same rounded size (a little smaller here) takes it back, zeroed.
        HugeArray<uint64_t> b(n - 1000);
        CHECK(b.data() == first);
        CHECK(huge_pages::parkedBytes() == 0);
        uint64_t nonZero = 0;
        for (size_t i = 0; i < b.size(); ++i) nonZero += b[i] != 0;
        CHECK(nonZero == 0);

        // A vector takes it back too (its elements are constructed anyway).
        b.release();
        {
            std::vector<uint64_t, HugePageAllocator<uint64_t>> v(n, 7);
            CHECK(v.data() == first);
            CHECK(std::count(v.begin(), v.end(), uint64_t(7)) == std::ptrdiff_t(n));
        }
        CHECK(huge_pages::parkedBytes() == huge_pages::roundUp(bytes));

        // A request of another size releases what is parked: the memory held
        // is never more than the last frame's.
        HugeArray<uint64_t> other(n * 3);
        CHECK(huge_pages::parkedBytes() == 0);
        other.release();
        CHECK(huge_pages::parkedBytes() == huge_pages::roundUp(n * 3 * sizeof(uint64_t)));
        {
            const huge_pages::ReuseScope nested;  // scopes nest
        }
        CHECK(huge_pages::parkedBytes() == huge_pages::roundUp(n * 3 * sizeof(uint64_t)));
    }
    CHECK(huge_pages::parkedBytes() == 0);  // the last scope released the rest
}
