#pragma once
// Byte-exact message building for the distributed renderer: values are copied
// with memcpy, so floats and doubles arrive bit for bit. Ranks are assumed to
// share one architecture (byte order, IEEE 754), as MPI_BYTE transfers do.

#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace raylab {

/// Appends trivially copyable values to a byte vector.
class ByteWriter {
public:
    explicit ByteWriter(std::vector<unsigned char>& out) : m_out(out) {}

    /// Appends the object representation of `v`.
    template <class T>
    void put(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>, "bytes of a trivially copyable type only");
        putBytes(&v, sizeof(T));
    }
    /// Appends `n` bytes from `p`.
    void putBytes(const void* p, size_t n) {
        const size_t at = m_out.size();
        m_out.resize(at + n);
        if (n) std::memcpy(m_out.data() + at, p, n);
    }
    /// Appends a length-prefixed string.
    void putString(const std::string& s) {
        put(uint32_t(s.size()));
        putBytes(s.data(), s.size());
    }

private:
    std::vector<unsigned char>& m_out;
};

/// Reads what ByteWriter wrote; throws std::runtime_error past the end.
class ByteReader {
public:
    ByteReader(const unsigned char* data, size_t size) : m_p(data), m_end(data + size) {}

    bool done() const { return m_p == m_end; }
    size_t left() const { return size_t(m_end - m_p); }

    /// Reads a value written by ByteWriter::put<T>.
    template <class T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>, "bytes of a trivially copyable type only");
        T v;
        getBytes(&v, sizeof(T));
        return v;
    }
    /// Copies the next `n` bytes to `p`.
    void getBytes(void* p, size_t n) {
        if (left() < n) throw std::runtime_error("message is truncated");
        if (n) std::memcpy(p, m_p, n);
        m_p += n;
    }
    /// Reads a string written by ByteWriter::putString.
    std::string getString() {
        const uint32_t n = get<uint32_t>();
        if (left() < n) throw std::runtime_error("message is truncated");
        std::string s(reinterpret_cast<const char*>(m_p), n);
        m_p += n;
        return s;
    }

private:
    const unsigned char* m_p;
    const unsigned char* m_end;
};

}  // namespace raylab
