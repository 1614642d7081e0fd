// What a rank sends rank 0: finished tiles or SPD corner rows, bit for bit,
// and the ray counters.

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "distributed_test_helpers.h"
#include "distributed/item_codec.h"
#include "support/float_bits.h"

using namespace raylab;
using raylab::test::bitsOf;
using raylab::test::floatFromBits;

namespace {

/// Every float of the film gets its own bit pattern, with the awkward ones
/// (a NaN with a payload, -0, the smallest subnormal, +inf) mixed in.
void fillDistinct(Film& f) {
    uint32_t k = 0;
    const auto next = [&k]() -> float {
        ++k;
        switch (k % 5) {
            case 0: return floatFromBits(0x7fc01234u + k);        // quiet NaN, payload
            case 1: return floatFromBits(0x80000000u);            // -0
            case 2: return floatFromBits(0x00000001u + (k << 8));  // subnormal
            case 3: return std::numeric_limits<float>::infinity();
            default: return floatFromBits(0x3f800000u + k);       // 1 + k ulp
        }
    };
    for (auto* layer : {&f.rgba, &f.z, &f.distance, &f.normal, &f.albedo, &f.objectId})
        for (float& v : *layer) v = next();
    for (MatteEntry& m : f.mattes) {
        m.object = int32_t(bitsOf(next()));
        m.coverage = next();
    }
}

bool pixelEqual(const Film& a, const Film& b, int x, int y) {
    const size_t i = a.index(x, y);
    for (int c = 0; c < 4; ++c)
        if (bitsOf(a.rgba[4 * i + c]) != bitsOf(b.rgba[4 * i + c])) return false;
    for (int c = 0; c < 3; ++c)
        if (bitsOf(a.normal[3 * i + c]) != bitsOf(b.normal[3 * i + c]) ||
            bitsOf(a.albedo[3 * i + c]) != bitsOf(b.albedo[3 * i + c]))
            return false;
    if (a.matteRanks != b.matteRanks) return false;
    for (int r = 0; r < a.matteRanks; ++r) {
        const MatteEntry& ma = a.mattesOf(i)[r];
        const MatteEntry& mb = b.mattesOf(i)[r];
        if (ma.object != mb.object || bitsOf(ma.coverage) != bitsOf(mb.coverage)) return false;
    }
    return bitsOf(a.z[i]) == bitsOf(b.z[i]) && bitsOf(a.distance[i]) == bitsOf(b.distance[i]) &&
           bitsOf(a.objectId[i]) == bitsOf(b.objectId[i]);
}

std::unique_ptr<test::PreparedScene> smallScene(bool spd) {
    RenderOverrides o;
    o.width = 40;
    o.height = 20;
    o.spd = spd;
    return test::prepare(std::string(RAYLAB_SOURCE_DIR) + "/scenes/primitives.json", o);
}

}  // namespace

TEST_CASE("ItemCodec: tiles travel bit for bit, other pixels stay untouched") {
    const auto p = smallScene(false);
    const FrameRenderer frame(p->scene, *p->accel, p->options, p->effects);
    // 40x20 pixels in 16x16 tiles: 3 columns (16, 16, 8 wide) x 2 rows (16, 4 high).
    REQUIRE(frame.workItemCount() == 6);
    const ItemCodec codec(frame, p->options);
    // Item 2: x 32..39, y 0..15 = 128 pixels of 13 floats and, at the
    // scene's 4 samples per pixel, 4 Cryptomatte ranks of 8 bytes (52 + 32 =
    // 84 bytes) + the item number.
    REQUIRE(p->options.spp == 4);
    CHECK(codec.itemBytes(2) == 4 + 128 * 84);
    // Item 5: x 32..39, y 16..19 = 32 pixels.
    CHECK(codec.itemBytes(5) == 4 + 32 * 84);

    FrameBuffers from = frame.makeBuffers();
    fillDistinct(from.film);
    std::vector<unsigned char> msg;
    codec.append(2, from, msg);
    codec.append(0, from, msg);
    CHECK(msg.size() == codec.itemBytes(2) + codec.itemBytes(0));

    FrameBuffers to = frame.makeBuffers();
    const FrameBuffers untouched = frame.makeBuffers();
    std::vector<int> items;
    ByteReader in(msg.data(), msg.size());
    codec.extract(in, to, items);
    CHECK(items == std::vector<int>{2, 0});
    for (int y = 0; y < 20; ++y) {
        for (int x = 0; x < 40; ++x) {
            const bool sent = y < 16 && (x < 16 || x >= 32);  // tiles 0 and 2
            REQUIRE_MESSAGE(pixelEqual(to.film, sent ? from.film : untouched.film, x, y),
                            "pixel " << x << "," << y);
        }
    }
}

TEST_CASE("ItemCodec: SPD corner rows and their pixel row's AOV layers travel bit for bit") {
    const auto p = smallScene(true);
    const FrameRenderer frame(p->scene, *p->accel, p->options, p->effects);
    // SPD mode: one item per row of corners, 21 rows of 41 corners.
    REQUIRE(frame.workItemCount() == 21);
    const ItemCodec codec(frame, p->options);
    // A corner: 3 doubles, a hit byte and an int32 object id (29 bytes);
    // corner row y < 20 also carries pixel row y's AOV layers (9 floats per
    // pixel: z, distance, N, albedo, objectId); the last one none. The
    // Cryptomatte ranks are not sent: rank 0 makes them from the corners.
    CHECK(codec.itemBytes(3) == 4 + 41 * 29 + 40 * 36);
    CHECK(codec.itemBytes(20) == 4 + 41 * 29);

    FrameBuffers from = frame.makeBuffers();
    REQUIRE(from.corners.size() == size_t(41) * 21);
    for (size_t i = 0; i < from.corners.size(); ++i) {
        CornerSample& s = from.corners[i];
        const double d = double(i);
        s.c = Color(d + 0.1, -d, std::nextafter(d, 1e9));
        s.hit = i % 2 == 1;
        s.objectId = int32_t(i % 7) - 1;
    }
    fillDistinct(from.film);
    std::vector<unsigned char> msg;
    codec.append(20, from, msg);
    codec.append(3, from, msg);
    FrameBuffers to = frame.makeBuffers();
    const FrameBuffers untouched = frame.makeBuffers();
    std::vector<int> items;
    ByteReader in(msg.data(), msg.size());
    codec.extract(in, to, items);
    CHECK(items == std::vector<int>{20, 3});
    for (int row = 0; row < 21; ++row) {
        for (int x = 0; x < 41; ++x) {
            const size_t i = size_t(row) * 41 + size_t(x);
            const CornerSample& a = to.corners[i];
            const CornerSample& b = (row == 3 || row == 20) ? from.corners[i] : untouched.corners[i];
            REQUIRE(bitsOf(a.c.r) == bitsOf(b.c.r));
            REQUIRE(bitsOf(a.c.g) == bitsOf(b.c.g));
            REQUIRE(bitsOf(a.c.b) == bitsOf(b.c.b));
            REQUIRE(a.hit == b.hit);
            REQUIRE(a.objectId == b.objectId);
        }
    }
    // The AOV layers of pixel row 3 arrived; RGBA is made later from the
    // corners (finishRow), so it stays as it was, like every other row.
    for (int y = 0; y < 20; ++y) {
        for (int x = 0; x < 40; ++x) {
            const size_t i = to.film.index(x, y);
            const Film& aovs = y == 3 ? from.film : untouched.film;
            for (int c = 0; c < 3; ++c) {
                REQUIRE(bitsOf(to.film.normal[3 * i + c]) == bitsOf(aovs.normal[3 * i + c]));
                REQUIRE(bitsOf(to.film.albedo[3 * i + c]) == bitsOf(aovs.albedo[3 * i + c]));
            }
            REQUIRE(bitsOf(to.film.z[i]) == bitsOf(aovs.z[i]));
            REQUIRE(bitsOf(to.film.distance[i]) == bitsOf(aovs.distance[i]));
            REQUIRE(bitsOf(to.film.objectId[i]) == bitsOf(aovs.objectId[i]));
            for (int c = 0; c < 4; ++c)
                REQUIRE(bitsOf(to.film.rgba[4 * i + c]) == bitsOf(untouched.film.rgba[4 * i + c]));
            REQUIRE(to.film.matteRanks == untouched.film.matteRanks);
            for (int r = 0; r < to.film.matteRanks; ++r) {
                const MatteEntry& got = to.film.mattesOf(i)[r];
                const MatteEntry& was = untouched.film.mattesOf(i)[r];
                REQUIRE(got.object == was.object);
                REQUIRE(bitsOf(got.coverage) == bitsOf(was.coverage));
            }
        }
    }
}

TEST_CASE("ItemCodec: malformed messages are refused") {
    const auto p = smallScene(false);
    const FrameRenderer frame(p->scene, *p->accel, p->options, p->effects);
    const ItemCodec codec(frame, p->options);
    FrameBuffers buffers = frame.makeBuffers();
    std::vector<unsigned char> msg;
    codec.append(1, buffers, msg);
    std::vector<int> items;

    SUBCASE("truncated") {
        msg.pop_back();
        ByteReader in(msg.data(), msg.size());
        CHECK_THROWS_WITH(codec.extract(in, buffers, items), "message is truncated");
        CHECK(items.empty());
    }
    SUBCASE("item out of range") {
        const int32_t bad = 6;  // items are 0..5
        std::memcpy(msg.data(), &bad, sizeof bad);
        ByteReader in(msg.data(), msg.size());
        CHECK_THROWS_WITH(codec.extract(in, buffers, items),
                          "message names work item 6 of a frame with 6");
    }
}

TEST_CASE("appendCounters / readCounters: every counter round-trips") {
    WorkCounters c;
    uint64_t k = 1;
    for (auto& perType : c.rays.byDepth)
        for (uint64_t& n : perType) n = (k++) * 0x9E3779B97F4A7C15ULL;  // distinct, large
    c.rays.cameraHits = 12345678901234ULL;
    c.nonFinite = 7;
    c.cappedSamples = 9;
    c.maxSampleRays = 65538;
    std::vector<unsigned char> bytes;
    appendCounters(c, bytes);
    // 4 ray types x 65 depths + camera hits, non-finite, capped, most rays: 8 bytes each.
    CHECK(bytes.size() == (4 * 65 + 4) * 8);
    ByteReader in(bytes.data(), bytes.size());
    const WorkCounters back = readCounters(in);
    CHECK(in.done());
    CHECK(test::sameCounters(back.rays, c.rays));
    CHECK(back.nonFinite == 7);
    CHECK(back.cappedSamples == 9);
    CHECK(back.maxSampleRays == 65538);
}

TEST_CASE("WorkCounters +=: sums, and the largest sample") {
    WorkCounters a, b;
    a.nonFinite = 1;
    a.cappedSamples = 2;
    a.maxSampleRays = 70;
    a.rays.cameraHits = 5;
    b.nonFinite = 10;
    b.cappedSamples = 20;
    b.maxSampleRays = 30;
    b.rays.cameraHits = 6;
    a += b;
    CHECK(a.nonFinite == 11);
    CHECK(a.cappedSamples == 22);
    CHECK(a.maxSampleRays == 70);
    CHECK(a.rays.cameraHits == 11);
}
