#include "renderer/file_content_hash.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <vector>

#include "renderer/content_hash.h"

namespace raylab {

namespace {

constexpr uint64_t kOffsetBasis = 0xcbf29ce484222325ull;  // FNV-1a 64's
constexpr uint64_t kPrime = 0x100000001b3ull;

/// Up to 8 bytes as a little-endian word on any machine (one load on x86).
uint64_t littleEndianWord(const unsigned char* p, size_t n) {
    uint64_t w = 0;
    for (size_t i = 0; i < n; ++i) w |= uint64_t(p[i]) << (8 * i);
    return w;
}

}  // namespace

uint64_t blockContentHash(std::string_view block) {
    const auto* p = reinterpret_cast<const unsigned char*>(block.data());
    const size_t words = block.size() / 8;
    uint64_t state = kOffsetBasis;
    for (size_t i = 0; i < words; ++i) state = (state ^ littleEndianWord(p + 8 * i, 8)) * kPrime;
    if (const size_t rest = block.size() % 8; rest > 0)
        state = (state ^ littleEndianWord(p + 8 * words, rest)) * kPrime;
    return state;
}

uint64_t fileContentHash(std::string_view bytes) {
    const size_t blocks = (bytes.size() + kFileHashBlock - 1) / kFileHashBlock;
    std::vector<uint64_t> hashes(blocks);
    if (blocks == 1) {
        // A scene file, an MTL: no threads (nor their start-up) for one block.
        hashes[0] = blockContentHash(bytes);
    } else {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, blocks, 1),
                          [&](const tbb::blocked_range<size_t>& r) {
            for (size_t b = r.begin(); b != r.end(); ++b)
                hashes[b] = blockContentHash(bytes.substr(b * kFileHashBlock, kFileHashBlock));
        });
    }
    ContentHash all;
    all.addNumber(bytes.size());
    for (uint64_t h : hashes) all.addNumber(h);
    return all.value();
}

}  // namespace raylab
