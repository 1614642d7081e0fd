// TransmittanceAccumulator: the crossings of a filtered shadow feeler, kept
// inline up to four and on the heap beyond; duplicates dropped; the product
// in one canonical order, so it has the same bits whatever order the
// crossings arrive in.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "renderer/accel/transmittance.h"

using namespace raylab;

namespace {

struct Crossing {
    uint32_t object, prim;
    double t;
    Color kt;
};

bool sameBits(const Color& a, const Color& b) {
    return std::memcmp(&a.r, &b.r, sizeof(double)) == 0 &&
           std::memcmp(&a.g, &b.g, sizeof(double)) == 0 &&
           std::memcmp(&a.b, &b.b, sizeof(double)) == 0;
}

Color productOf(const std::vector<Crossing>& crossings, size_t* size = nullptr) {
    TransmittanceAccumulator acc;
    for (const Crossing& c : crossings) acc.add(c.object, c.prim, c.t, c.kt);
    if (size) *size = acc.size();
    return acc.product();
}

}  // namespace

TEST_CASE("transmittance: nothing crossed lets all the light through") {
    TransmittanceAccumulator acc;
    CHECK(acc.size() == 0);
    const Color c = acc.product();
    CHECK(c.r == 1.0);
    CHECK(c.g == 1.0);
    CHECK(c.b == 1.0);
}

TEST_CASE("transmittance: hand-computed products, inline and spilled") {
    // Two crossings: 0.5 * 0.25 = 0.125 (exact in binary).
    size_t n = 0;
    Color c = productOf({{0, 0, 1.0, Color(0.5, 0.5, 1.0)}, {1, 0, 2.0, Color(0.25, 1.0, 0.5)}}, &n);
    CHECK(n == 2);
    CHECK(c.r == 0.125);
    CHECK(c.g == 0.5);
    CHECK(c.b == 0.5);
    // Six crossings (past the four kept inline): 0.5^6 in red, exactly.
    std::vector<Crossing> six;
    for (uint32_t i = 0; i < 6; ++i) six.push_back({i, 0, 1.0 + i, Color(0.5, 1.0, 0.75)});
    c = productOf(six, &n);
    CHECK(n == 6);
    CHECK(c.r == 0.015625);
    CHECK(c.g == 1.0);
    CHECK(c.b == 0.177978515625);  // 0.75^6 = 729/4096, exact
}

TEST_CASE("transmittance: a crossing reported twice counts once, before and after the spill") {
    for (const size_t distinct : {1u, 3u, 4u, 5u, 9u}) {
        std::vector<Crossing> all;
        for (uint32_t i = 0; i < distinct; ++i) all.push_back({i % 3, i, 0.5 * i, Color(0.5)});
        // Every crossing again (Embree may report a primitive twice).
        const std::vector<Crossing> once = all;
        all.insert(all.end(), once.begin(), once.end());
        size_t n = 0;
        const Color c = productOf(all, &n);
        CHECK(n == distinct);
        CHECK(c.r == std::ldexp(1.0, -int(distinct)));
    }
    // Same object and primitive at another t is another crossing.
    size_t n = 0;
    productOf({{2, 7, 1.0, Color(0.5)}, {2, 7, 1.5, Color(0.5)}, {2, 7, 1.0, Color(0.5)}}, &n);
    CHECK(n == 2);
}

TEST_CASE("transmittance: the same bits for every arrival order") {
    // Factors whose product rounds differently in different orders.
    std::vector<Crossing> crossings;
    const double factors[] = {0.1, 0.7, 0.3, 0.9, 0.11, 0.13, 0.17};
    for (uint32_t i = 0; i < 7; ++i)
        crossings.push_back({i % 2, i, 0.25 * i, Color(factors[i], factors[6 - i], 0.3)});
    // The product in the canonical order, (object, prim, t), computed here.
    const auto canonicalProduct = [](std::vector<Crossing> sorted) {
        std::sort(sorted.begin(), sorted.end(), [](const Crossing& a, const Crossing& b) {
            if (a.object != b.object) return a.object < b.object;
            if (a.prim != b.prim) return a.prim < b.prim;
            return a.t < b.t;
        });
        Color c(1.0);
        for (const Crossing& x : sorted) c = c * x.kt;
        return c;
    };
    const auto byPrim = [](const Crossing& a, const Crossing& b) { return a.prim < b.prim; };
    for (size_t count : {3u, 4u, 5u, 7u}) {
        std::vector<Crossing> some(crossings.begin(), crossings.begin() + long(count));
        const Color expected = canonicalProduct(some);
        std::sort(some.begin(), some.end(), byPrim);
        int orders = 0, differ = 0;
        do {
            differ += !sameBits(productOf(some), expected);
            ++orders;
        } while (std::next_permutation(some.begin(), some.end(), byPrim));
        CHECK(differ == 0);
        CHECK(orders > 1);
    }
    CHECK(sameBits(productOf(crossings), canonicalProduct(crossings)));
}

TEST_CASE("transmittance: an opaque crossing blocks all light") {
    TransmittanceAccumulator acc;
    for (uint32_t i = 0; i < 6; ++i) acc.add(i, 0, 1.0 + i, Color(0.5));
    CHECK_FALSE(acc.blocked());
    acc.block();
    CHECK(acc.blocked());
    CHECK(acc.product().isBlack());
}
