// The hand-out order and the guided chunk sizes of the distributed renderer.

#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "distributed/work_schedule.h"

using namespace raylab;

TEST_CASE("scatteredOrder: golden-ratio stride through the items") {
    // n = 10: round(10 / φ) = round(6.18) = 6 shares the factor 2 with 10,
    // so the stride is 7: 0, 7, 14 mod 10 = 4, 11 mod 10 = 1, 8, 5, 2, 9, 6, 3.
    CHECK(scatteredOrder(10) == std::vector<int>{0, 7, 4, 1, 8, 5, 2, 9, 6, 3});
    // n = 8: round(4.94) = 5, coprime to 8: 0, 5, 10-8 = 2, 7, 12-8 = 4, 1, 6, 3.
    CHECK(scatteredOrder(8) == std::vector<int>{0, 5, 2, 7, 4, 1, 6, 3});
    CHECK(scatteredOrder(1) == std::vector<int>{0});
    CHECK(scatteredOrder(0).empty());
}

TEST_CASE("scatteredOrder: a permutation for every size") {
    for (int n = 1; n <= 300; ++n) {
        std::vector<int> order = scatteredOrder(n);
        std::sort(order.begin(), order.end());
        std::vector<int> identity(static_cast<size_t>(n));
        std::iota(identity.begin(), identity.end(), 0);
        REQUIRE_MESSAGE(order == identity, "n = " << n);
    }
}

TEST_CASE("scatteredOrder: the first chunk of a tile grid covers every band of rows") {
    // The demo at 640x480 has 40x30 tiles. The first 1/8 of the hand-out
    // order (150 tiles: the first chunk of two ranks) must touch every band
    // of 5 tile rows, not just the top of the image as scan order would.
    const std::vector<int> order = scatteredOrder(40 * 30);
    std::vector<int> perBand(6, 0);
    for (int i = 0; i < 150; ++i) ++perBand[size_t(order[size_t(i)] / 40 / 5)];
    for (int band = 0; band < 6; ++band) {
        CHECK_MESSAGE(perBand[size_t(band)] >= 20, "band " << band);  // 25 on average
    }
}

TEST_CASE("GuidedSchedule: chunks of ceil(remaining / 2P) shrinking to one item") {
    // 100 items, 2 ranks (divisor 4): 100 -> 25, 75 -> 19, 56 -> 14,
    // 42 -> 11, 31 -> 8, 23 -> 6, 17 -> 5, 12 -> 3, 9 -> 3, 6 -> 2, then 1s.
    GuidedSchedule s(100, 2);
    std::vector<int> sizes;
    int expectedBegin = 0;
    for (WorkChunk c = s.next(); c.count > 0; c = s.next()) {
        CHECK(c.begin == expectedBegin);
        expectedBegin += c.count;
        sizes.push_back(c.count);
    }
    CHECK(sizes == std::vector<int>{25, 19, 14, 11, 8, 6, 5, 3, 3, 2, 1, 1, 1, 1});
    CHECK(s.remaining() == 0);
    CHECK(s.next().count == 0);  // stays empty
}

TEST_CASE("GuidedSchedule: one rank, no items") {
    GuidedSchedule one(5, 1);  // divisor 2: 5 -> 3, 2 -> 1, 1 -> 1
    CHECK(one.next().count == 3);
    CHECK(one.next().count == 1);
    CHECK(one.next().count == 1);
    CHECK(one.next().count == 0);
    GuidedSchedule none(0, 4);
    CHECK(none.remaining() == 0);
    CHECK(none.next().count == 0);
}
