// igzip streams placed where ISA-L's output cannot depend on their address
// (renderer/io/igzip_stream.h): the hash igzip takes of the stream's address,
// the placement, and the bytes of streams at different addresses.
#include <doctest/doctest.h>
#include <isa-l/igzip_lib.h>

#include <cstdint>
#include <memory>
#include <set>
#include <vector>

#if defined(__x86_64__)
#include <nmmintrin.h>
#endif

#include "renderer/io/igzip_stream.h"

using namespace raylab;

namespace {

/// CRC-32C bit by bit (reflected polynomial 0x82F63B78, initial value 0, no
/// final xor), the definition crc32c32's table must agree with.
uint32_t crc32cBitwise(uint32_t v) {
    uint32_t c = v;
    for (int i = 0; i < 32; ++i) c = (c >> 1) ^ (0x82F63B78u & (0u - (c & 1u)));
    return c;
}

#if defined(__x86_64__)
/// The crc32 instruction igzip's hash uses.
__attribute__((target("sse4.2"))) uint32_t crc32cInstruction(uint32_t v) {
    return _mm_crc32_u32(0, v);
}
#endif

/// in's zlib stream from `s` (zeroed and initialised here): stateless at
/// `level` (as the EXR writer), or stateful level 1 (as the PNG writer).
std::vector<uint8_t> deflateWith(isal_zstream* s, const std::vector<uint8_t>& in, int level,
                                 bool stateless) {
    *s = isal_zstream{};
    const size_t levelBytes = level == 2 ? ISAL_DEF_LVL2_DEFAULT : ISAL_DEF_LVL1_DEFAULT;
    auto levelBuffer = std::make_unique<uint8_t[]>(levelBytes);
    std::vector<uint8_t> out(in.size() + 1024);
    if (stateless)
        isal_deflate_stateless_init(s);
    else
        isal_deflate_init(s);
    s->level = uint32_t(level);
    s->level_buf = levelBuffer.get();
    s->level_buf_size = uint32_t(levelBytes);
    s->gzip_flag = IGZIP_ZLIB;
    s->flush = NO_FLUSH;
    s->end_of_stream = 1;
    s->next_in = const_cast<uint8_t*>(in.data());
    s->avail_in = uint32_t(in.size());
    s->next_out = out.data();
    s->avail_out = uint32_t(out.size());
    if (stateless) {
        REQUIRE(isal_deflate_stateless(s) == COMP_OK);
    } else {
        while (s->avail_in > 0 || s->internal_state.state != ZSTATE_END)
            REQUIRE(isal_deflate(s) == COMP_OK);
    }
    out.resize(s->total_out);
    return out;
}

/// Inputs whose first 4-grams fall in few buckets: a PNG row of filter type
/// 1 then zeros (positions 1 and 2 both in bucket 0), rows of a flat image,
/// and bytes with little repetition.
std::vector<std::vector<uint8_t>> sampleInputs() {
    std::vector<std::vector<uint8_t>> inputs;
    std::vector<uint8_t> row(481, 0);
    row[0] = 1;
    inputs.push_back(row);
    std::vector<uint8_t> rows;
    for (int y = 0; y < 16; ++y) {
        rows.push_back(uint8_t(y % 5));
        for (int x = 0; x < 96; ++x) rows.push_back(uint8_t(x < 40 ? 0x80 : (x * 7 + y) & 0xFF));
    }
    inputs.push_back(rows);
    std::vector<uint8_t> noise(4000);
    uint32_t state = 12345;
    for (uint8_t& b : noise) {
        state = state * 1664525u + 1013904223u;
        b = uint8_t((state >> 24) & 0x3F);
    }
    inputs.push_back(noise);
    return inputs;
}

}  // namespace

TEST_CASE("igzip stream: crc32c32 is CRC-32C as the crc32 instruction computes it") {
    CHECK(crc32c32(0) == 0u);  // zero data from a zero register stays zero
    // Computed by hand with the bit-by-bit definition (Python, the same loop).
    CHECK(crc32c32(1) == 0xDD45AAB8u);
    CHECK(crc32c32(0x80000000u) == 0x82F63B78u);  // the top bit leaves last: the polynomial
    uint32_t v = 0x9E3779B9u;
    for (int i = 0; i < 20000; ++i) {
        v = v * 2654435761u + 0x6B43A9B5u;
        REQUIRE(crc32c32(v) == crc32cBitwise(v));
#if defined(__x86_64__)
        if (__builtin_cpu_supports("sse4.2")) REQUIRE(crc32c32(v) == crc32cInstruction(v));
#endif
    }
    CHECK(igzipAddressBucket(reinterpret_cast<void*>(uintptr_t(0x1234) << 16)) ==
          (crc32cBitwise(0x1234) & 0x7FFFu));
    // Bits 0..15 of the address do not matter.
    CHECK(igzipAddressBucket(reinterpret_cast<void*>((uintptr_t(0x1234) << 16) | 0xFFFF)) ==
          igzipAddressBucket(reinterpret_cast<void*>(uintptr_t(0x1234) << 16)));
}

TEST_CASE("igzip stream: every stream in use has its own address, in bucket kIgzipBucket") {
    std::set<const void*> seen;
    {
        IgzipStream a, b, c;
        for (const IgzipStream* s : {&a, &b, &c}) {
            CHECK(igzipAddressBucket(s->get()) == kIgzipBucket);
            seen.insert(s->get());
        }
        CHECK(seen.size() == 3);
    }
    // Given back to the pool, then taken again: no new placement.
    IgzipStream again;
    CHECK(seen.count(again.get()) == 1);
    CHECK(igzipAddressBucket(again.get()) == kIgzipBucket);
}

TEST_CASE("igzip stream: the bytes follow the address bucket, so placed streams agree") {
    // Two streams in each of two buckets, at different addresses.
    isal_zstream* const inBucket3[] = {placeIgzipStream(kIgzipBucket), placeIgzipStream(kIgzipBucket)};
    isal_zstream* const inBucket0[] = {placeIgzipStream(0), placeIgzipStream(0)};
    for (isal_zstream* s : {inBucket3[0], inBucket3[1], inBucket0[0], inBucket0[1]}) REQUIRE(s);
    CHECK(inBucket3[0] != inBucket3[1]);
    CHECK(inBucket0[0] != inBucket0[1]);
    CHECK(igzipAddressBucket(inBucket0[1]) == 0u);

    int differing = 0;  // (input, path) pairs whose bytes differ between the buckets
    for (const std::vector<uint8_t>& in : sampleInputs()) {
        for (const auto& entry : {std::pair{1, false}, {1, true}, {2, true}}) {
            // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
            const auto& level = entry.first;
            const auto& stateless = entry.second;
            CAPTURE(in.size());
            CAPTURE(level);
            CAPTURE(stateless);
            const auto a = deflateWith(inBucket3[0], in, level, stateless);
            CHECK(deflateWith(inBucket3[1], in, level, stateless) == a);
            const auto b = deflateWith(inBucket0[0], in, level, stateless);
            CHECK(deflateWith(inBucket0[1], in, level, stateless) == b);
            differing += a != b;
        }
    }
    // What the placement exists for: ISA-L 2.30 writes other bytes for a
    // stream in another bucket. If this fails, the installed ISA-L no longer
    // hashes the stream's address and the placement could go.
    CHECK(differing > 0);
}
