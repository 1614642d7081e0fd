#pragma once
// A fixed-size array of zero bytes on huge pages (huge_page_allocator.h's
// 2 MiB-aligned mappings), for the large temporaries of a mesh build. A
// std::vector cannot give this: malloc's mappings are not 2 MiB-aligned, so
// their first and last partial 2 MiB fault 4 KiB at a time (up to 1024
// faults of ~10-20 µs each on this project's VMs), and resize() writes every
// element once more in one thread. Fresh mappings are zero already (a
// mapping parked by huge_pages::ReuseScope is zeroed when taken back).

#include <cstddef>
#include <cstring>
#include <type_traits>

#include "renderer/huge_page_allocator.h"

namespace raylab {

/// Elements start as all-zero bytes (0, 0.0, a zero Vec3, a zero std::atomic);
/// no constructor or destructor runs, so T must be trivially destructible and
/// valid as zero bytes.
template <class T>
class HugeArray {
    static_assert(std::is_trivially_destructible_v<T>);

public:
    HugeArray() = default;
    explicit HugeArray(size_t n) : m_size(n) {
        if (n == 0) return;
        if (n > size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
        bool fresh = false;
        m_data = static_cast<T*>(huge_pages::allocate(n * sizeof(T), &fresh));
        // Fresh pages are zero already; operator new's small blocks and
        // mappings parked by a ReuseScope are not.
        if (!fresh) std::memset(static_cast<void*>(m_data), 0, n * sizeof(T));
    }
    ~HugeArray() { release(); }
    HugeArray(HugeArray&& o) noexcept : m_data(o.m_data), m_size(o.m_size) {
        o.m_data = nullptr;
        o.m_size = 0;
    }
    HugeArray& operator=(HugeArray&& o) noexcept {
        if (this != &o) {
            release();
            m_data = o.m_data;
            m_size = o.m_size;
            o.m_data = nullptr;
            o.m_size = 0;
        }
        return *this;
    }
    HugeArray(const HugeArray&) = delete;
    HugeArray& operator=(const HugeArray&) = delete;

    T& operator[](size_t i) { return m_data[i]; }
    const T& operator[](size_t i) const { return m_data[i]; }
    T* data() { return m_data; }
    const T* data() const { return m_data; }
    size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    /// Frees the memory now; the array is empty after.
    void release() {
        if (m_data) huge_pages::deallocate(m_data, m_size * sizeof(T));
        m_data = nullptr;
        m_size = 0;
    }

private:
    T* m_data = nullptr;
    size_t m_size = 0;
};

}  // namespace raylab
