#pragma once
// The content hash readTextFile records for every file it reads, which MPI
// ranks compare (distributed/render_identity.h). FNV-1a's step (xor, then
// multiply by the FNV prime) taken over 8-byte little-endian words instead of
// bytes, in blocks of 1 MiB hashed in parallel; then the length and the block
// hashes go through ContentHash. Eight times fewer steps than contentHash and
// split over the cores: a 60 MB OBJ costs a few milliseconds, not 100 ms of
// one core. The same promise as contentHash: a change confined to one byte
// always changes it (it changes one word of one block; every step is a
// bijection of the state for a fixed word, and of the word for a fixed state),
// and the value is the same for any thread count (the blocks are fixed).

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace raylab {

/// Bytes per block of fileContentHash: fixed, so the value never depends on threads.
constexpr size_t kFileHashBlock = size_t(1) << 20;

/// The word-wise FNV-1a of one block: full words, then the last 1-7 bytes as
/// one word padded with zero bytes (the length, added by fileContentHash,
/// tells "ab" from "ab\0").
uint64_t blockContentHash(std::string_view block);

/// ContentHash of (size, blockContentHash of each kFileHashBlock-byte block in order).
uint64_t fileContentHash(std::string_view bytes);

}  // namespace raylab
