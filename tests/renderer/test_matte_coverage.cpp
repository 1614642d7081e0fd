// A pixel's object coverage for the Cryptomatte layers (MatteCoverage):
// ranks by coverage, ties by object index, unused ranks {-1, 0}, values
// checked against hand-computed fractions.

#include <doctest/doctest.h>

#include <array>

#include "renderer/film.h"
#include "renderer/matte_coverage.h"

using namespace raylab;

namespace {

std::array<MatteEntry, kMatteRanks> stored(const MatteCoverage& m, double divisor = 1.0) {
    std::array<MatteEntry, kMatteRanks> out;
    for (MatteEntry& e : out) e = MatteEntry{7, 7.f};  // overwritten, every rank
    m.store({out.data(), out.size()}, divisor);
    return out;
}

void checkUnused(const std::array<MatteEntry, kMatteRanks>& out, int from) {
    for (int r = from; r < kMatteRanks; ++r) {
        CAPTURE(r);
        CHECK(out[r].object == -1);
        CHECK(out[r].coverage == 0.f);
    }
}

}  // namespace

TEST_CASE("MatteCoverage: no object, one object, two objects, ties, a divisor") {
    MatteCoverage none;
    none.add(-1, 0.25);  // a miss adds nothing
    checkUnused(stored(none), 0);

    MatteCoverage one;
    for (int k = 0; k < 4; ++k) one.add(5, 0.25);
    auto out = stored(one);
    CHECK(out[0].object == 5);
    CHECK(out[0].coverage == 1.0f);  // 0.25 four times is exactly 1
    checkUnused(out, 1);
    out = stored(one, 4.0);
    CHECK(out[0].coverage == 0.25f);

    MatteCoverage two;
    two.add(9, 0.25);
    two.add(2, 0.25);
    two.add(9, 0.25);
    two.add(-1, 0.25);  // the background's quarter is in no rank
    out = stored(two);
    CHECK(out[0].object == 9);
    CHECK(out[0].coverage == 0.5f);
    CHECK(out[1].object == 2);
    CHECK(out[1].coverage == 0.25f);
    checkUnused(out, 2);

    MatteCoverage tie;
    tie.add(8, 1);
    tie.add(3, 1);
    out = stored(tie, 2.0);
    CHECK(out[0].object == 3);  // equal coverage: the lower index first
    CHECK(out[1].object == 8);
    CHECK(out[0].coverage == 0.5f);
    CHECK(out[1].coverage == 0.5f);
    checkUnused(out, 2);
}

TEST_CASE("MatteCoverage: more objects than inline slots and ranks keep the largest") {
    // Objects 0..11 with weights 1..12: the six ranks are objects 11..6.
    MatteCoverage many;
    for (int object = 0; object < 12; ++object) many.add(object, double(object + 1));
    const auto out = stored(many, 78.0);  // 1 + 2 + ... + 12
    for (int r = 0; r < kMatteRanks; ++r) {
        CAPTURE(r);
        CHECK(out[r].object == 11 - r);
        CHECK(out[r].coverage == float(double(12 - r) / 78.0));
    }
}

TEST_CASE("MatteCoverage::clear: a reused coverage stores what a fresh one does") {
    // The render loop clears one coverage per pixel; entries of the last
    // pixel (inline and spilled) must not reach the next one's ranks.
    MatteCoverage reused;
    for (int object = 0; object < 12; ++object) reused.add(object, double(object + 1));
    reused.clear();
    checkUnused(stored(reused), 0);
    reused.add(4, 0.25);
    reused.add(10, 0.5);  // object 10 sat in the spill before the clear
    reused.add(4, 0.25);
    MatteCoverage fresh;
    fresh.add(4, 0.25);
    fresh.add(10, 0.5);
    fresh.add(4, 0.25);
    const auto a = stored(reused), b = stored(fresh);
    for (int r = 0; r < kMatteRanks; ++r) {
        CAPTURE(r);
        CHECK(a[r].object == b[r].object);
        CHECK(a[r].coverage == b[r].coverage);
    }
    CHECK(a[0].object == 4);  // tie at 0.5: the lower index first
    CHECK(a[0].coverage == 0.5f);
    CHECK(a[1].object == 10);
    checkUnused(a, 2);
}

TEST_CASE("MatteCoverage::storeSingle writes what store() gives for one object or none") {
    // An SPD pixel whose four corners hit object 5: four quarters.
    MatteCoverage four;
    for (int k = 0; k < 4; ++k) four.add(5, 0.25);
    std::array<MatteEntry, kMatteRanks> direct;
    for (MatteEntry& e : direct) e = MatteEntry{7, 7.f};
    MatteCoverage::storeSingle({direct.data(), direct.size()}, 5, 1.0f);
    const auto gathered = stored(four);
    for (int r = 0; r < kMatteRanks; ++r) {
        CAPTURE(r);
        CHECK(direct[r].object == gathered[r].object);
        CHECK(direct[r].coverage == gathered[r].coverage);
    }
    CHECK(direct[0].object == 5);
    CHECK(direct[0].coverage == 1.f);
    checkUnused(direct, 1);
    // Four background corners: no object at all.
    MatteCoverage none;
    for (int k = 0; k < 4; ++k) none.add(-1, 0.25);
    MatteCoverage::storeSingle({direct.data(), direct.size()}, -1, 1.0f);
    checkUnused(direct, 0);
    checkUnused(stored(none), 0);
}

TEST_CASE("MatteCoverage: a film's shorter rank stride gets exactly its entries") {
    // Film::matteRanks = 4 (an SPD film): store and storeSingle write four
    // entries and nothing beyond them; the four largest coverages are kept.
    MatteCoverage m;
    for (int object = 0; object < 5; ++object) m.add(object, double(object + 1));
    std::array<MatteEntry, 6> out;
    for (MatteEntry& e : out) e = MatteEntry{99, 9.f};
    m.store({out.data(), 4}, 15.0);  // 1 + 2 + 3 + 4 + 5
    for (int r = 0; r < 4; ++r) {
        CAPTURE(r);
        CHECK(out[r].object == 4 - r);
        CHECK(out[r].coverage == float(double(5 - r) / 15.0));
    }
    CHECK(out[4].object == 99);
    CHECK(out[5].object == 99);
    MatteCoverage::storeSingle({out.data(), 2}, 3, 0.5f);
    CHECK(out[0].object == 3);
    CHECK(out[0].coverage == 0.5f);
    CHECK(out[1].object == -1);
    CHECK(out[2].object == 2);  // beyond the span: untouched
}

TEST_CASE("matteRanksOfSampling: the most objects one pixel's samples can see") {
    RenderOptions o;
    o.spp = 1;
    CHECK(matteRanksOfSampling(o) == 1);
    o.spp = 3;
    CHECK(matteRanksOfSampling(o) == 3);
    o.spp = 64;
    CHECK(matteRanksOfSampling(o) == kMatteRanks);
    o.spp = 1;
    o.spd = true;
    CHECK(matteRanksOfSampling(o) == 4);  // the four corners
    o.spd = false;
    o.adaptiveThreshold = 0.1;
    CHECK(matteRanksOfSampling(o) == kMatteRanks);
}
