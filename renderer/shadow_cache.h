#pragma once
// Haines' shadow cache (Haines & Greenberg, "The Light Buffer", IEEE CG&A
// 1986, in a simple form): per worker thread, the primitive that last
// blocked a light for the surface a feeler leaves. Neighbouring shading
// points of one surface are mostly shadowed by the same primitive, so the
// accelerator asks that one first (one exact Shape::occluded) and walks its
// BVH only when it does not block. The answers are the accelerator's own
// (Accelerator::occluded with an OcclusionHint); only the work to find them
// changes.
//
// Two slots name a guess for a feeler: the receiver's (its object, the light
// and the ray depth) and, as the fallback, the receiver's at any depth. Keyed
// by depth alone (one slot per light and depth, as this cache was first),
// reflections that alternate between surfaces evicted each other's
// occluders: gears left 2.6 times as many blocked feelers to a walk
// (docs/benchmarks.md, session 2026-12-06 05:20).
//
// The slots are direct-mapped tables of at most a fixed size: a scene with
// more receivers than slots shares them (a wrong guess costs one test), and
// the cache's memory stays small for any scene (fresh pages are dear).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "renderer/accel/accelerator.h"

namespace raylab {

class ShadowCache {
public:
    /// Most slots of each table: 64 Ki x 4 bytes (the receiver-and-depth
    /// table) and 16 Ki x 4 bytes (the receiver table) per worker, in rows of
    /// one slot per light. Smaller caps left more walks on large scenes
    /// (rings: 135 k -> 150 k with 16 Ki and 4 Ki).
    static constexpr size_t kDepthSlots = size_t(1) << 16;
    static constexpr size_t kReceiverSlots = size_t(1) << 14;

    /// Room for `objects` receivers, `lights` lights and ray depths
    /// 1..maxDepth (a camera ray's hit is at depth 1). Keeps the hints when
    /// the shape is already right: called for every camera ray.
    void prepare(size_t objects, size_t lights, int maxDepth) {
        const size_t depths = size_t(std::max(maxDepth, 1));
        if (objects == m_objects && lights == m_lights && depths == m_depths) return;
        m_objects = objects;
        m_lights = lights;
        m_depths = depths;
        // A row of `lights` slots per key (receiver and depth; receiver).
        m_depthRows = rows(objects * depths, kDepthSlots / std::max<size_t>(lights, 1));
        m_receiverRows = rows(objects, kReceiverSlots / std::max<size_t>(lights, 1));
        m_byDepth.assign(m_depthRows * lights, OcclusionHint::kNone);
        m_byReceiver.assign(m_receiverRows * lights, OcclusionHint::kNone);
    }

    /// The slot rows of receiver `object` at ray depth `depth` (after
    /// prepare; found once for all of a hit's feelers).
    struct Receiver {
        uint32_t* atDepth;
        uint32_t* anyDepth;
    };
    Receiver receiver(uint32_t object, int depth) {
        // A depth outside 1..maxDepth only shares another key's row.
        const size_t depthRow = row(size_t(object) * m_depths + size_t(depth - 1), m_depthRows);
        const size_t receiverRow = row(object, m_receiverRows);
        return {m_byDepth.data() + depthRow * m_lights, m_byReceiver.data() + receiverRow * m_lights};
    }

    /// The two slots of a feeler from `r` to `light`: its guesses, and where
    /// its answer goes (valid until the next prepare).
    struct Slots {
        uint32_t* atDepth;
        uint32_t* anyDepth;
        OcclusionHint hint() const { return {*atDepth, *anyDepth}; }
        /// What the accelerator answered for the feeler: its occluder, or
        /// none (a lit point forgets the occluder: its neighbours are likely
        /// lit too).
        void remember(const OcclusionHint& answered) const {
            *atDepth = answered.primitive;
            *anyDepth = answered.primitive;
        }
    };
    static Slots slots(const Receiver& r, size_t light) {
        return {r.atDepth + light, r.anyDepth + light};
    }

    /// Slots in both tables (0 before prepare): the cache's memory is
    /// 4 bytes a slot.
    size_t slotCount() const { return m_byDepth.size() + m_byReceiver.size(); }

private:
    /// Rows of a table: one per key, at most `most` (at least 1).
    static size_t rows(size_t keys, size_t most) { return std::max<size_t>(std::min(keys, most), 1); }
    /// A key's row: keys wrap around the rows, so consecutive objects get
    /// consecutive rows and the receivers a tile sees (mostly neighbours in
    /// the scene's order) rarely share one. The division is paid once per hit
    /// and only in a scene with more keys than rows.
    static size_t row(size_t key, size_t rows) { return key < rows ? key : key % rows; }

    size_t m_objects = 0, m_lights = 0, m_depths = 0;
    size_t m_depthRows = 1, m_receiverRows = 1;
    std::vector<uint32_t> m_byDepth;     ///< primitive per (object and depth, light)
    std::vector<uint32_t> m_byReceiver;  ///< primitive per (object, light)
};

}  // namespace raylab
