#pragma once
// Large arrays backed by transparent huge pages. On this project's machines
// (a VM, THP in "madvise" mode) the kernel's page faults cost a third of an
// OBJ load's CPU time when 250 MB are touched 4 KiB at a time; advised
// regions fault 2 MiB at a time. Contents and results are unchanged; the
// resident size can grow by at most one huge page per array.

#include <cstddef>
#include <vector>

namespace raylab {

/// Asks the kernel (madvise MADV_HUGEPAGE) to back the whole 2 MiB pages
/// inside [data, data + bytes) with huge pages. Does nothing for regions
/// smaller than 4 MiB or where the kernel refuses.
void adviseHugePages(const void* data, size_t bytes);

/// v.reserve(n), advised for huge pages before anything touches it.
template <class T>
void reserveHugePages(std::vector<T>& v, size_t n) {
    v.reserve(n);
    adviseHugePages(v.data(), v.capacity() * sizeof(T));
}

/// v.resize(n) on huge pages: reserved and advised first, then filled.
template <class T>
void resizeHugePages(std::vector<T>& v, size_t n, const T& value = T()) {
    reserveHugePages(v, n);
    v.resize(n, value);
}

}  // namespace raylab
