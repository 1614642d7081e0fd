#include "renderer/plane_arena.h"

namespace raylab {

PlaneArena::PlaneArena(size_t bytes) : m_size(bytes) {
    if (bytes > 0) m_base = static_cast<unsigned char*>(huge_pages::allocate(bytes));
}

PlaneArena::~PlaneArena() { huge_pages::deallocate(m_base, m_size); }

void* PlaneArena::take(size_t bytes) {
    const size_t need = slot(bytes);
    size_t used = m_used.load(std::memory_order_relaxed);
    do {
        if (need > m_size - used) return nullptr;
    } while (!m_used.compare_exchange_weak(used, used + need, std::memory_order_relaxed));
    return m_base + used;
}

}  // namespace raylab
