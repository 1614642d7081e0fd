#include "renderer/io/igzip_stream.h"

#include <sys/mman.h>

#include <isa-l/crc.h>

#include <cstring>
#include <memory>
#include <mutex>
#include <new>
#include <vector>

#if defined(__x86_64__)
#include <nmmintrin.h>
#endif

#ifndef MAP_FIXED_NOREPLACE
#define MAP_FIXED_NOREPLACE 0x100000  // Linux 4.17; older kernels take it as a hint
#endif

namespace raylab {

namespace {

/// Bytes mapped per placed stream.
constexpr size_t kStreamBytes = (sizeof(isal_zstream) + 4095) & ~size_t(4095);
/// Addresses are searched in 64 KiB steps (bits 0..15 do not matter), at
/// most this many mapping attempts per placement.
constexpr int kMaxAttempts = 64;

/// Streams no IgzipStream holds now, for the whole process.
struct Pool {
    std::mutex mutex;
    std::vector<isal_zstream*> free;  ///< capacity: every stream made so far
    size_t made = 0;
};
Pool& pool() {
    static Pool* p = new Pool;  // never destroyed: streams may be returned during exit
    return *p;
}

/// The largest 64 KiB page number below x (and above 16 MiB) whose bucket
/// is `bucket`, or 0. One in 2^15 is: tens of thousands of CRCs a search.
uint64_t bucketBelow(uint64_t x, uint32_t bucket) {
    if (x <= 0x101) return 0;  // nothing above 16 MiB below x (and no wrap-around)
    while (--x > 0x100)
        if ((crc32c32(uint32_t(x)) & kIgzipBucketMask) == bucket) return x;
    return 0;
}

#if defined(__x86_64__)
/// SSE4.2's crc32 instruction, which igzip's hash itself uses.
__attribute__((target("sse4.2"))) uint32_t crc32cInstruction(uint32_t v) {
    return _mm_crc32_u32(0, v);
}
#endif

}  // namespace

uint32_t crc32c32(uint32_t v) {
#if defined(__x86_64__)
    // A placement searches tens of thousands of addresses: the instruction
    // inline (~1 ns) rather than a library call over a 4-byte buffer (~20 ns,
    // 0.7 ms per placement).
    static const bool instruction = __builtin_cpu_supports("sse4.2");
    if (instruction) return crc32cInstruction(v);
#endif
    // ISA-L's iSCSI CRC is CRC-32C without the customary inversions: from
    // init 0 over v's four bytes, lowest first, it is the crc32 instruction's.
    unsigned char bytes[4];
    std::memcpy(bytes, &v, sizeof bytes);
    return crc32_iscsi(bytes, int(sizeof bytes), 0);
}

isal_zstream* placeIgzipStream(uint32_t bucket) {
    // Start below where the kernel puts a fresh mapping (the space under
    // the lowest mapping is mostly free) and walk down 64 KiB at a time to
    // the next address in the bucket (one in 2^15 is; computed, not mapped).
    void* probe = mmap(nullptr, kStreamBytes, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (probe == MAP_FAILED) return nullptr;
    uint64_t x = uint64_t(reinterpret_cast<uintptr_t>(probe)) >> 16;
    munmap(probe, kStreamBytes);
    for (int attempts = 0; attempts < kMaxAttempts;) {
        x = bucketBelow(x, bucket);
        if (x == 0) break;
        void* want = reinterpret_cast<void*>(uintptr_t(x) << 16);
        void* got = mmap(want, kStreamBytes, PROT_READ | PROT_WRITE,
                         MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED_NOREPLACE, -1, 0);
        if (got == want) return new (got) isal_zstream;  // fresh pages: already zero
        if (got != MAP_FAILED) munmap(got, kStreamBytes);  // a kernel that took it as a hint
        ++attempts;
    }
    return nullptr;
}

IgzipStream::IgzipStream() {
    {
        std::lock_guard<std::mutex> lock(pool().mutex);
        if (!pool().free.empty()) {
            m_stream = pool().free.back();
            pool().free.pop_back();
            return;
        }
    }
    m_stream = placeIgzipStream(kIgzipBucket);
    // No address found (never seen): a heap stream deflates correctly, its
    // bytes just may differ from run to run as they did before the placement.
    std::unique_ptr<isal_zstream> heap;
    if (!m_stream) m_stream = (heap = std::make_unique<isal_zstream>()).get();
    // Room to give it back without allocating (the destructor cannot throw).
    std::lock_guard<std::mutex> lock(pool().mutex);
    pool().free.reserve(++pool().made);
    heap.release();  // owned by the pool from here on, as a placed stream is
}

IgzipStream::~IgzipStream() {
    std::lock_guard<std::mutex> lock(pool().mutex);
    pool().free.push_back(m_stream);  // within the capacity reserved when it was made
}

void IgzipStream::reset() { std::memset(static_cast<void*>(m_stream), 0, sizeof(isal_zstream)); }

}  // namespace raylab
