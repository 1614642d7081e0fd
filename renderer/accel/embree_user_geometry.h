#pragma once
// Every primitive that is not a native Embree triangle goes into ONE Embree
// user geometry (Mitsuba's adaptor pattern, STYLE.md §2.3): its generic bounds /
// intersect / occluded callbacks forward to the pure Shape methods, so a new
// primitive needs no Embree code. Embree's primID indexes a table of
// (shape, primitive, object) entries in scene order.
//
// Analytic shapes are intersected with the caller's exact double ray, carried
// in an extended RTCIntersectContext, so their t, u, v are bit-identical to
// the naive loop's. Internal to renderer/accel (and white-box tests).

#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

#include "geometry/ray.h"
#include "geometry/shape.h"
#include "renderer/accel/embree_device.h"
#include "renderer/accel/transmittance.h"
#include "renderer/surface_filter.h"

namespace raylab {

/// \brief Per-query data reaching the user-geometry callbacks through Embree's
///   context pointer (the only pointer Embree guarantees to pass unchanged).
/// \details Every field is set by init(), which each query calls first; until
///   then they are indeterminate (a packet keeps 16 lane contexts, and zeroing
///   all of them showed in its profile). A new field must be set in init().
struct EmbreeQueryContext {
    RTCIntersectContext rtc;  ///< Embree's context; must stay the first member
    /// The caller's exact double ray, or null: shapes are then tested against
    /// Embree's float copy of the ray (made relative to the origin). Set only
    /// for rtcIntersect1/rtcOccluded1: one context cannot describe the rays of
    /// a packet or stream, and incoherent streams call back with N = 1.
    const Ray* ray;
    double tMin;   ///< exclusive lower bound, double (exact path only)
    double bestT;  ///< closest user-geometry hit so far; starts at tMax
    double bestU;  ///< its shape parameters
    double bestV;
    uint32_t bestEntry;  ///< its entry in the table
    bool exactHit;   ///< a hit was recorded from `ray`
    /// Decides about candidates on filtered objects (cut-outs, transmitters),
    /// or null: every candidate is a hit (bare replay).
    const SurfaceFilter* filter;
    /// Set for a transmittance query: occlusion candidates on transmitters are
    /// collected here instead of ending the query.
    TransmittanceAccumulator* shadow;
    /// Occlusion queries: the entry whose exact test found the occluder, or
    /// OcclusionHint::kNone (none yet, or a native triangle occluded).
    uint32_t occluderEntry;
    /// The object the ray departs from (Departure), or kNone: its entries
    /// answer "no hit" without their test (exact path only).
    uint32_t departed;
    /// A packet's exact lanes (EmbreeAccelerator::intersectPacket): the
    /// double ray, interval and best hit of the ray whose id is i are
    /// lanes[i]'s; null for single rays.
    EmbreeQueryContext* lanes;

    /// Prepares the context for one query of `ray` (may be null) over (tMin,
    /// tMax) that leaves out object `departedObject` (Departure; none by default).
    void init(const Ray* r, double tMinimum, double tMax,
              uint32_t departedObject = 0xffffffffu) {
        rtcInitIntersectContext(&rtc);
        ray = r;
        tMin = tMinimum;
        bestT = tMax;
        bestU = bestV = 0;
        bestEntry = 0;
        exactHit = false;
        filter = nullptr;
        shadow = nullptr;
        occluderEntry = 0xffffffffu;
        departed = departedObject;
        lanes = nullptr;
    }
};

/// User data of the user geometry (read by the callbacks).
struct EmbreeUserTable {
    struct Entry {
        const Shape* shape;
        uint32_t prim;
        uint32_t object;  ///< index into Scene::objects
        bool cutsOut;     ///< every query shows its candidates to the surface filter
        bool transmits;   ///< transmits and has no cut-out: shown to the filter only by
                          ///< filtered-shadow feelers (transmittance)
    };
    std::vector<Entry> entries;    ///< indexed by Embree's primID
    std::vector<RTCBounds> boxes;  ///< primID -> padded float box, relative to origin
    Vec3 origin;                   ///< to rebuild world rays from Embree's float lanes
    IntersectOptions options;      ///< handed to every shape query
};

/// \brief Creates the user geometry over `table` (which must outlive the
///   scene) and attaches it to `scene`. \return its geomID.
unsigned attachUserGeometry(const EmbreeDevice& device, RTCScene scene,
                            const EmbreeUserTable& table, RTCBuildQuality quality);

}  // namespace raylab
