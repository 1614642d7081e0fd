#pragma once
// A 64-bit hash of bytes: FNV-1a (Fowler, Noll, Vo), one xor and one multiply
// per byte. It is for telling accidentally different inputs apart (two MPI
// ranks that loaded different scene files): a change confined to one byte
// always changes it (each step is a bijection of the state), and two
// unrelated inputs collide with a chance of about 2^-64. It is no defence
// against someone who crafts a collision on purpose; nothing here needs one.

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace raylab {

class ContentHash {
public:
    /// Adds `n` bytes at `data`.
    ContentHash& add(const void* data, size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < n; ++i) {
            m_state ^= p[i];
            m_state *= 0x100000001b3ull;  // the 64-bit FNV prime
        }
        return *this;
    }
    ContentHash& add(std::string_view bytes) { return add(bytes.data(), bytes.size()); }

    /// Adds the 8 bytes of `v`, least significant first (any machine), e.g. a
    /// length between two strings so that ("ab", "c") and ("a", "bc") differ.
    ContentHash& addNumber(uint64_t v) {
        for (int i = 0; i < 8; ++i) {
            const unsigned char b = static_cast<unsigned char>(v >> (8 * i));
            add(&b, 1);
        }
        return *this;
    }

    uint64_t value() const { return m_state; }

private:
    uint64_t m_state = 0xcbf29ce484222325ull;  // the 64-bit FNV offset basis
};

/// The hash of `bytes` alone.
inline uint64_t contentHash(std::string_view bytes) { return ContentHash().add(bytes).value(); }

}  // namespace raylab
