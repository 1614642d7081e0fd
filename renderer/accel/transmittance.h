#pragma once
// The candidates a filtered shadow feeler crosses, and their product. The
// accelerators meet them in traversal order (Embree's BVH order differs from
// the naive loop's scene order, and may report a primitive twice), so they
// are collected, duplicates dropped, and multiplied in one canonical order:
// the product is the same bits in both accelerators and for any BVH.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "shading/color.h"

namespace raylab {

class TransmittanceAccumulator {
public:
    /// One crossing of primitive `prim` of `object` at ray parameter t.
    void add(uint32_t object, uint32_t prim, double t, const Color& transmission) {
        for (const Crossing& c : m_crossings)
            if (c.object == object && c.prim == prim && c.t == t) return;  // reported again
        m_crossings.push_back({object, prim, t, transmission});
    }
    /// An opaque surface was crossed: no light arrives.
    void block() { m_blocked = true; }
    bool blocked() const { return m_blocked; }
    /// Distinct crossings collected.
    size_t size() const { return m_crossings.size(); }

    /// The product of every crossing's transmission, in (object, prim, t) order.
    Color product() {
        if (m_blocked) return Color{};
        std::sort(m_crossings.begin(), m_crossings.end(), [](const Crossing& a, const Crossing& b) {
            if (a.object != b.object) return a.object < b.object;
            if (a.prim != b.prim) return a.prim < b.prim;
            return a.t < b.t;
        });
        Color c(1.0);
        for (const Crossing& x : m_crossings) c = c * x.transmission;
        return c;
    }

private:
    struct Crossing {
        uint32_t object, prim;
        double t;
        Color transmission;
    };
    std::vector<Crossing> m_crossings;
    bool m_blocked = false;
};

}  // namespace raylab
