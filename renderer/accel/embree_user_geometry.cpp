#include "renderer/accel/embree_user_geometry.h"

#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>

#include "renderer/accel/embree_float.h"

namespace raylab {

// The callbacks recover the extended context from Embree's pointer to its
// first member; that cast is only valid for a standard-layout struct.
static_assert(std::is_standard_layout<EmbreeQueryContext>::value,
              "EmbreeQueryContext must be standard-layout");
static_assert(offsetof(EmbreeQueryContext, rtc) == 0, "rtc must be the first member");

namespace {

const EmbreeUserTable& tableOf(void* geometryUserPtr) {
    return *static_cast<const EmbreeUserTable*>(geometryUserPtr);
}

EmbreeQueryContext& contextOf(RTCIntersectContext* context) {
    return *reinterpret_cast<EmbreeQueryContext*>(context);
}

/// World-space double ray of lane i of Embree's float ray data (packet and
/// bare-replay queries, which carry no double ray).
Ray laneRay(RTCRayN* rays, unsigned n, unsigned i, const Vec3& origin) {
    const Vec3 o{RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i)};
    const Vec3 d{RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i)};
    return Ray{o + origin, d};
}

/// The first of the entry's hits from `h` on (in (tMin, tMax)) that the
/// filter does not cut out. Out of line: only cut-outs need it.
[[gnu::noinline]] std::optional<ShapeHit> firstUncut(const EmbreeUserTable::Entry& e,
                                                     std::optional<ShapeHit> h, const Ray& ray,
                                                     double tMax, const IntersectOptions& opt,
                                                     const SurfaceFilter& filter) {
    while (h && filter.cutOut(ray, Hit{h->t, e.object, e.prim, h->u, h->v}))
        h = e.shape->intersect(e.prim, ray, h->t, tMax, opt);  // the next crossing
    return h;
}

/// The first hit on the entry in (tMin, tMax) that the filter does not cut out.
inline std::optional<ShapeHit> firstKeptHit(const EmbreeUserTable::Entry& e, const Ray& ray,
                                            double tMin, double tMax,
                                            const IntersectOptions& opt,
                                            const SurfaceFilter* filter) {
    std::optional<ShapeHit> h = e.shape->intersect(e.prim, ray, tMin, tMax, opt);
    if (!e.cutsOut || !filter) return h;  // cutOut() is false for every other entry
    return firstUncut(e, h, ray, tMax, opt, *filter);
}

/// Whether a shadow feeler over (tMin, tMax) is stopped by a filtered entry.
/// Opaque shadows (no accumulator): any kept crossing stops it. Filtered
/// shadows: transmitting crossings are collected and let it pass.
bool filteredEntryBlocks(const EmbreeUserTable::Entry& e, const Ray& ray, double tMin,
                         double tMax, const IntersectOptions& opt, const SurfaceFilter& filter,
                         TransmittanceAccumulator* shadow) {
    for (double from = tMin;;) {
        const auto h = e.shape->intersect(e.prim, ray, from, tMax, opt);
        if (!h) return false;
        from = h->t;
        const Hit candidate{h->t, e.object, e.prim, h->u, h->v};
        if (filter.cutOut(ray, candidate)) continue;
        if (!shadow) return true;
        const Color c = filter.transmission(ray, candidate);
        if (c.isBlack()) {
            shadow->block();
            return true;
        }
        shadow->add(e.object, e.prim, h->t, c);
    }
}

void boundsCallback(const RTCBoundsFunctionArguments* args) {
    // Computed from Shape::bounds(prim) once at build time (where bad bounds
    // can still throw); the userPtr argument of rtcSetGeometryBoundsFunction is
    // ignored by Embree 3.13.5, so the table comes from geometryUserPtr.
    *args->bounds_o = tableOf(args->geometryUserPtr).boxes[args->primID];
}

/// Lane i of an intersect callback's n rays. Exact: the lane is the single
/// ray whose double copy the context carries (n = 1, i = 0, known here at
/// compile time, so the lane's fields are plain loads and stores: this is
/// every query EmbreeAccelerator makes). Otherwise Embree's float lane is
/// tested (bare replays without a double ray, packets, streams).
template <bool Exact>
inline void intersectLane(const RTCIntersectFunctionNArguments* args,
                          const EmbreeUserTable& table, EmbreeQueryContext& ctx, unsigned n,
                          unsigned i) {
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, n);
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, n);
    const uint32_t entry = args->primID;
    const EmbreeUserTable::Entry& e = table.entries[entry];
    float& tfar = RTCRayN_tfar(rays, n, i);
    std::optional<ShapeHit> h;
    if constexpr (Exact) {
        if (e.object == ctx.departed) return;  // the ray cannot meet it again
        // Strict tMin < t < best-so-far in double (Shape contract). Exact
        // ties (coplanar surfaces, e.g. a cone's cap on the floor) go to
        // the lower entry (scene order), as in the naive loop, which visits
        // objects in order: so the limit is opened by one ulp for a
        // lower entry and the tie is settled here.
        const bool winsTies = ctx.exactHit && entry < ctx.bestEntry;
        const double tMax =
            winsTies ? std::nextafter(ctx.bestT, std::numeric_limits<double>::infinity())
                     : ctx.bestT;
        h = firstKeptHit(e, *ctx.ray, ctx.tMin, tMax, table.options, ctx.filter);
        if (h && !(h->t < ctx.bestT || (winsTies && h->t == ctx.bestT))) return;
    } else {
        h = firstKeptHit(e, laneRay(rays, n, i, table.origin), RTCRayN_tnear(rays, n, i), tfar,
                         table.options, ctx.filter);
    }
    if (!h) return;
    // A triangle may already have shrunk tfar below this (double) hit.
    const float t = static_cast<float>(h->t);
    if (!(t <= tfar)) return;

    // Embree wants every hit field written, but raylab never reads Ng
    // (Scene::surfaceAt computes the exact normal for the winning hit),
    // so a cheap stand-in facing the ray saves a surfaceAt per candidate.
    tfar = t;
    RTCHitN_Ng_x(hits, n, i) = -RTCRayN_dir_x(rays, n, i);
    RTCHitN_Ng_y(hits, n, i) = -RTCRayN_dir_y(rays, n, i);
    RTCHitN_Ng_z(hits, n, i) = -RTCRayN_dir_z(rays, n, i);
    RTCHitN_u(hits, n, i) = static_cast<float>(h->u);
    RTCHitN_v(hits, n, i) = static_cast<float>(h->v);
    RTCHitN_primID(hits, n, i) = args->primID;
    RTCHitN_geomID(hits, n, i) = args->geomID;
    RTCHitN_instID(hits, n, i, 0) = args->context->instID[0];
    if constexpr (Exact) {
        ctx.bestT = h->t;
        ctx.bestU = h->u;
        ctx.bestV = h->v;
        ctx.bestEntry = entry;
        ctx.exactHit = true;
    }
}

/// How a callback tests lane i of its n rays (intersectLane, occludedLane).
template <class Args>
using LaneTest = void (*)(const Args*, const EmbreeUserTable&, EmbreeQueryContext&, unsigned,
                          unsigned);

/// Every valid lane of Embree's float rays. Out of line, so that the exact
/// single ray's path does not pay for this loop's registers.
template <class Args, LaneTest<Args> FloatLane>
[[gnu::noinline]] void floatLanes(const Args* args, const EmbreeUserTable& table,
                                  EmbreeQueryContext& ctx) {
    for (unsigned i = 0; i < args->N; ++i)
        if (args->valid[i] == -1) FloatLane(args, table, ctx, args->N, i);
}

/// The callback's ray data (intersect and occlusion callbacks differ).
inline RTCRayN* raysOf(const RTCIntersectFunctionNArguments* args) {
    return RTCRayHitN_RayN(args->rayhit, args->N);
}
inline RTCRayN* raysOf(const RTCOccludedFunctionNArguments* args) { return args->ray; }

/// Every valid lane of a packet whose context carries one exact context per
/// lane (EmbreeAccelerator::intersectPacket): each lane is tested exactly as
/// a single ray with that lane's double ray and best hit. The lane is named
/// by the ray's id, not by its place in the callback: Embree may hand a
/// packet to the callbacks in smaller pieces or one ray at a time (an SSE
/// device emulates rtcIntersect8).
template <class Args, LaneTest<Args> ExactLane>
[[gnu::noinline]] void exactLanes(const Args* args, const EmbreeUserTable& table,
                                  EmbreeQueryContext& ctx) {
    RTCRayN* rays = raysOf(args);
    for (unsigned i = 0; i < args->N; ++i)
        if (args->valid[i] == -1)
            ExactLane(args, table, ctx.lanes[RTCRayN_id(rays, args->N, i)], args->N, i);
}

/// The intersect and occlusion callbacks. Queries from EmbreeAccelerator
/// carry the exact double rays (one, or one per packet lane), so the shape
/// computes the same answer as in the naive loop; every other query tests
/// the float lanes.
template <class Args, LaneTest<Args> ExactLane, LaneTest<Args> FloatLane>
void laneCallback(const Args* args) {
    const EmbreeUserTable& table = tableOf(args->geometryUserPtr);
    EmbreeQueryContext& ctx = contextOf(args->context);
    if (args->N == 1 && ctx.ray != nullptr) {
        if (args->valid[0] == -1) ExactLane(args, table, ctx, 1, 0);
        return;
    }
    if (ctx.lanes != nullptr) {
        exactLanes<Args, ExactLane>(args, table, ctx);
        return;
    }
    floatLanes<Args, FloatLane>(args, table, ctx);
}

/// Lane i of an occlusion callback's n rays; Exact as for intersectLane.
template <bool Exact>
inline void occludedLane(const RTCOccludedFunctionNArguments* args, const EmbreeUserTable& table,
                         EmbreeQueryContext& ctx, unsigned n, unsigned i) {
    RTCRayN* rays = args->ray;
    const EmbreeUserTable::Entry& e = table.entries[args->primID];
    if (Exact && e.object == ctx.departed) return;  // the ray cannot meet it again
    float& tfar = RTCRayN_tfar(rays, n, i);
    // A transmitter stops an opaque feeler at its first crossing, which is
    // what its exact test answers; only filtered shadows collect its kt.
    const bool filtered = ctx.filter && (e.cutsOut || (e.transmits && ctx.shadow));
    bool hit;
    if (filtered) {
        hit = Exact ? filteredEntryBlocks(e, *ctx.ray, ctx.tMin, ctx.bestT, table.options,
                                          *ctx.filter, ctx.shadow)
                    : filteredEntryBlocks(e, laneRay(rays, n, i, table.origin),
                                          RTCRayN_tnear(rays, n, i), tfar, table.options,
                                          *ctx.filter, ctx.shadow);
    } else {
        hit = Exact ? e.shape->occluded(e.prim, *ctx.ray, ctx.tMin, ctx.bestT, table.options)
                    : e.shape->occluded(e.prim, laneRay(rays, n, i, table.origin),
                                        RTCRayN_tnear(rays, n, i), tfar, table.options);
        // Named for the shadow cache: its exact test alone is the answer.
        if (Exact && hit) ctx.occluderEntry = args->primID;
    }
    if (hit) tfar = -kInfF;  // Embree's "occluded" marker
}

}  // namespace

unsigned attachUserGeometry(const EmbreeDevice& device, RTCScene scene,
                            const EmbreeUserTable& table, RTCBuildQuality quality) {
    // Creation order from NUMERICS.md §1: count, user data, callbacks, commit, attach.
    EmbreeGeometry geom(device, RTC_GEOMETRY_TYPE_USER);
    device.check("rtcNewGeometry(USER)");
    rtcSetGeometryUserPrimitiveCount(geom.get(), static_cast<unsigned>(table.entries.size()));
    rtcSetGeometryUserData(geom.get(), const_cast<EmbreeUserTable*>(&table));
    rtcSetGeometryBoundsFunction(geom.get(), &boundsCallback, nullptr);
    rtcSetGeometryIntersectFunction(
        geom.get(), &laneCallback<RTCIntersectFunctionNArguments, intersectLane<true>,
                                  intersectLane<false>>);
    rtcSetGeometryOccludedFunction(
        geom.get(), &laneCallback<RTCOccludedFunctionNArguments, occludedLane<true>,
                                  occludedLane<false>>);
    rtcSetGeometryBuildQuality(geom.get(), quality);
    rtcCommitGeometry(geom.get());
    device.check("user geometry setup");
    const unsigned id = rtcAttachGeometry(scene, geom.get());
    device.check("rtcAttachGeometry(USER)");
    // geom's destructor releases our reference; the scene keeps its own.
    return id;
}

}  // namespace raylab
