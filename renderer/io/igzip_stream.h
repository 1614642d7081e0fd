#pragma once
// igzip streams whose output cannot depend on where they live.
//
// ISA-L 2.30's level 1 and 2 deflate (igzip_icf_body_h1_gr_bt.asm, label
// .write_first_byte, the SSE4.2/AVX2/AVX-512 builds) hashes input position 2
// with crc32c((uint32_t)(stream >> 16)), the isal_zstream's own address,
// where it means input bytes 2..5. That hash bucket, masked by the hash
// table's size (at most 2^15 buckets), decides which matches are found, so
// the compressed bytes changed with address space layout: about 3 processes
// in 1,000 wrote another valid PNG or EXR for the same pixels (measured:
// docs/benchmarks.md, "igzip's output and the stream's address").
//
// The fix from our side: every stream sits at an address whose bucket has
// the same low 15 bits (kIgzipBucket), found by searching 64 KiB-aligned
// addresses and mapping the stream there. Then the bytes depend on the input
// alone, for every hash table size. Placed streams are pooled for the whole
// process: a placement costs a search and a mapping, a reuse nothing.

#include <isa-l/igzip_lib.h>

#include <cstdint>

namespace raylab {

/// The low 15 bits every placed stream's address bucket has. Odd, so never
/// the bucket of four zero bytes (0) under any table size, and none of the
/// buckets of PNG rows' first 4-grams (a filter byte then zeros or 0xFF),
/// uniform bytes or common half floats: for such inputs the bytes are the
/// ones igzip wrote most of the time before.
constexpr uint32_t kIgzipBucket = 3;
/// The bucket bits that can matter: level 2's table has 2^15 buckets.
constexpr uint32_t kIgzipBucketMask = 0x7FFF;

/// CRC-32C of the 32-bit value v with initial value 0 and no final xor: what
/// the crc32 instruction computes from (0, v), igzip's hash.
uint32_t crc32c32(uint32_t v);

/// The bucket igzip's first body call uses for a stream at `stream` (low 15
/// bits; a table of 2^k buckets uses the low k of them).
inline uint32_t igzipAddressBucket(const void* stream) {
    return crc32c32(uint32_t(reinterpret_cast<uintptr_t>(stream) >> 16)) & kIgzipBucketMask;
}

/// An isal_zstream at an address in bucket kIgzipBucket, taken from the
/// process's pool (placed anew when the pool is empty) and given back on
/// destruction. Its contents are whatever the last user left: zero it
/// (reset()) before isal_deflate_init / isal_deflate_stateless_init.
class IgzipStream {
public:
    IgzipStream();
    ~IgzipStream();
    IgzipStream(const IgzipStream&) = delete;
    IgzipStream& operator=(const IgzipStream&) = delete;

    isal_zstream* get() const { return m_stream; }
    isal_zstream* operator->() const { return m_stream; }
    /// Zeroes the stream: the inits leave fields the deflate reads.
    void reset();

private:
    isal_zstream* m_stream;
};

/// \brief Maps a zeroed isal_zstream at an address with
///   igzipAddressBucket() == bucket (< 2^15), for tests; never unmapped.
///   Null if no address was found (the pool then falls back to the heap).
isal_zstream* placeIgzipStream(uint32_t bucket);

}  // namespace raylab
