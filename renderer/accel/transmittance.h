#pragma once
// The candidates a filtered shadow feeler crosses, and their product. The
// accelerators meet them in traversal order (Embree's BVH order differs from
// the naive loop's scene order, and may report a primitive twice), so they
// are collected, duplicates dropped, and multiplied in one canonical order:
// the product is the same bits in both accelerators and for any BVH.

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "shading/color.h"

namespace raylab {

class TransmittanceAccumulator {
public:
    /// One crossing of primitive `prim` of `object` at ray parameter t.
    void add(uint32_t object, uint32_t prim, double t, const Color& transmission) {
        for (const Crossing* c = begin(); c != end(); ++c)
            if (c->object == object && c->prim == prim && c->t == t) return;  // reported again
        const Crossing added{object, prim, t, transmission};
        if (m_size < kInline) {
            m_inline[m_size] = added;
        } else {
            // Past the inline room: every crossing moves to the heap.
            if (m_size == kInline) m_spilled.assign(m_inline.begin(), m_inline.end());
            m_spilled.push_back(added);
        }
        ++m_size;
    }
    /// An opaque surface was crossed: no light arrives.
    void block() { m_blocked = true; }
    bool blocked() const { return m_blocked; }
    /// Distinct crossings collected.
    size_t size() const { return m_size; }

    /// The product of every crossing's transmission, in (object, prim, t) order.
    Color product() {
        if (m_blocked) return Color{};
        std::sort(begin(), end(), [](const Crossing& a, const Crossing& b) {
            if (a.object != b.object) return a.object < b.object;
            if (a.prim != b.prim) return a.prim < b.prim;
            return a.t < b.t;
        });
        Color c(1.0);
        for (const Crossing* x = begin(); x != end(); ++x) c = c * x->transmission;
        return c;
    }

private:
    struct Crossing {
        uint32_t object, prim;
        double t;
        Color transmission;
    };
    /// Crossings kept inside the accumulator: a feeler crosses few
    /// transmitters, and one is made per filtered shadow query (a heap
    /// block per query cost more than the query's own bookkeeping).
    static constexpr size_t kInline = 4;

    Crossing* begin() { return m_size > kInline ? m_spilled.data() : m_inline.data(); }
    Crossing* end() { return begin() + m_size; }

    size_t m_size = 0;
    std::array<Crossing, kInline> m_inline;  ///< the first kInline crossings (unset beyond m_size)
    std::vector<Crossing> m_spilled;         ///< all of them, once there are more
    bool m_blocked = false;
};

}  // namespace raylab
