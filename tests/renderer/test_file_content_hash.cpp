// The hash readTextFile records for MPI ranks to compare: FNV-1a's step over
// 8-byte words in fixed 1 MiB blocks. Expected values computed by hand with
// Python's integers (the step (state ^ word) * 0x100000001b3 mod 2^64, words
// little-endian, the last one padded with zero bytes; then FNV-1a 64 over the
// length and the block hashes, each as 8 little-endian bytes).

#include <doctest/doctest.h>

#include <tbb/global_control.h>

#include <cstdint>
#include <string>
#include <vector>

#include "renderer/content_hash.h"
#include "renderer/file_content_hash.h"

using namespace raylab;

TEST_CASE("blockContentHash: FNV-1a's step over little-endian words, the tail zero-padded") {
    CHECK(blockContentHash("") == 0xcbf29ce484222325ull);  // no step: the offset basis
    // One step: (0xcbf29ce484222325 ^ 0x6867666564636261) * 0x100000001b3.
    CHECK(blockContentHash("abcdefgh") == 0x3919eeb00ee1e68cull);
    CHECK(blockContentHash("abcdefghij") == 0xe89d7a294942691full);
    // The padding makes "ab" and "ab\0" one word: the length tells them apart.
    CHECK(blockContentHash("ab") == 0xaf81dc4c8634e68cull);
    CHECK(blockContentHash(std::string("ab\0", 3)) == 0xaf81dc4c8634e68cull);
}

TEST_CASE("fileContentHash: the length and the block hashes through ContentHash") {
    CHECK(fileContentHash("") == 0xa8c7f832281a39c5ull);
    CHECK(fileContentHash("abcdefghij") == 0x5f5901863644a170ull);
    CHECK(fileContentHash("ab") == 0x2c45f1a4f5808c2full);
    CHECK(fileContentHash(std::string("ab\0", 3)) == 0x3cc1c27affe94d6eull);
    CHECK(fileContentHash("abcdefghij") ==
          ContentHash().addNumber(10).addNumber(blockContentHash("abcdefghij")).value());
}

namespace {
std::string threeBlocksAndABit() {
    std::string big(3 * kFileHashBlock + 5, '\0');
    for (size_t i = 0; i < big.size(); ++i) big[i] = char((i * 7 + 3) % 251);
    return big;
}
}  // namespace

TEST_CASE("fileContentHash: several blocks, the same value for any thread count") {
    const std::string big = threeBlocksAndABit();
    CHECK(fileContentHash(big) == 0x834aa5a3ef92dd38ull);
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    CHECK(fileContentHash(big) == 0x834aa5a3ef92dd38ull);
}

TEST_CASE("fileContentHash: a change of one byte anywhere changes it") {
    std::string big = threeBlocksAndABit();
    const uint64_t original = fileContentHash(big);
    int unchanged = 0, tried = 0;
    // The 16 bytes around each block boundary, the last bytes, and bytes spread over the blocks.
    std::vector<size_t> places;
    for (size_t b = 0; b <= 3; ++b)
        for (size_t k = 0; k < 16; ++k)
            if (b * kFileHashBlock + k >= 8 && b * kFileHashBlock + k - 8 < big.size())
                places.push_back(b * kFileHashBlock + k - 8);
    for (size_t at = big.size() - 6; at < big.size(); ++at) places.push_back(at);
    for (size_t at = 3; at < big.size(); at += 40961) places.push_back(at);
    for (size_t at : places) {
        for (int value : {0, 1, 0x80, 0xFF}) {
            if (char(value) == big[at]) continue;
            const char was = big[at];
            big[at] = char(value);
            unchanged += fileContentHash(big) == original;
            ++tried;
            big[at] = was;
        }
    }
    CHECK(tried > 300);
    CHECK(unchanged == 0);
    // Swapping two blocks' contents is a change too (the blocks keep their order).
    std::string swapped = big.substr(kFileHashBlock, kFileHashBlock) +
                          big.substr(0, kFileHashBlock) + big.substr(2 * kFileHashBlock);
    CHECK(fileContentHash(swapped) != original);
}
