#include "renderer/accel/embree_accelerator.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <exception>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include <emmintrin.h>

#include "renderer/accel/embree_factory.h"
#include "renderer/accel/embree_float.h"
#include "renderer/accel/embree_triangles.h"
#include "renderer/timing.h"

namespace raylab {

namespace {

RTCBuildQuality toEmbree(AccelOptions::BvhQuality q) {
    switch (q) {
        case AccelOptions::BvhQuality::Low:
            return RTC_BUILD_QUALITY_LOW;
        case AccelOptions::BvhQuality::Medium:
            return RTC_BUILD_QUALITY_MEDIUM;
        case AccelOptions::BvhQuality::High:
            return RTC_BUILD_QUALITY_HIGH;
    }
    return RTC_BUILD_QUALITY_MEDIUM;
}

/// Runs `f`, naming the object in any std::invalid_argument it throws.
template <class F>
auto namingObject(const Object& object, F&& f) {
    try {
        return f();
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("embree: object '" + object.name + "' (" +
                                    object.shape->kind() + "): " + e.what());
    }
}

}  // namespace

EmbreeAccelerator::EmbreeAccelerator(const Scene& scene, const AccelOptions& options,
                                     const std::string& deviceConfig)
    : m_device(deviceConfig), m_origin(options.origin), m_filter(scene, options),
      m_scene(m_device) {
    m_device.check("rtcNewScene");
    if (!isFinite(m_origin))
        throw std::invalid_argument("embree: accelerator origin must be finite");
    validateShapes(scene, "embree");
    const auto start = std::chrono::steady_clock::now();

    const RTCBuildQuality quality = toEmbree(options.quality);
    rtcSetSceneFlags(m_scene.get(), options.robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
    rtcSetSceneBuildQuality(m_scene.get(), quality);
    m_device.check("scene setup");
    m_nativePackets16 =
        rtcGetDeviceProperty(m_device.get(), RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) != 0;

    m_user.options = options.intersect;
    addUserGeometry(scene, quality);
    addTriangles(scene, quality);

    rtcCommitScene(m_scene.get());
    m_device.check("rtcCommitScene");

    for (const Object& o : scene.objects) m_shapes.push_back(o.shape.get());
    m_edgeHits.scene = m_scene.get();
    m_edgeHits.origin = m_origin;
    m_edgeHits.userGeomId = m_userGeomId;
    m_edgeHits.triangleGeoms = &m_triangleGeoms;
    m_edgeHits.shapes = &m_shapes;
    m_edgeHits.filter = &m_filter;
    m_edgeHits.options = options.intersect;
    m_buildSeconds = secondsSince(start);
}

void EmbreeAccelerator::addUserGeometry(const Scene& scene, RTCBuildQuality quality) {
    m_user.origin = m_origin;
    // Blocks of objects in parallel (SPD gears: 9,345 polygons, ~1 ms on one
    // thread before Embree's build), joined in object order: the table, and
    // the first error in object order, are what the serial loop gives.
    constexpr size_t kBlock = 512;
    const size_t objects = scene.objects.size();
    struct Part {
        std::vector<EmbreeUserTable::Entry> entries;
        std::vector<RTCBounds> boxes;
        std::exception_ptr error;
    };
    std::vector<Part> parts((objects + kBlock - 1) / kBlock);
    // Blocks after one that failed need not be made: its error, or an
    // earlier block's, is the one rethrown.
    std::atomic<size_t> firstFailed{parts.size()};
    tbb::parallel_for(size_t(0), parts.size(), [&](size_t b) {
        if (b > firstFailed.load(std::memory_order_relaxed)) return;
        Part& part = parts[b];
        std::vector<Bounds3> boxes;
        try {
            for (size_t i = b * kBlock; i < std::min(objects, (b + 1) * kBlock); ++i) {
                const Object& o = scene.objects[i];
                if (!o.shape || o.shape->nativeTriangles()) continue;
                const bool cutsOut = m_filter.cutsOut(uint32_t(i));
                const bool transmits = m_filter.filters(uint32_t(i)) && !cutsOut;
                for (uint32_t prim = 0; prim < o.shape->primitiveCount(); ++prim) {
                    // One entry per covering box, all naming the same primitive.
                    boxes.clear();
                    o.shape->appendCoveringBoxes(prim, m_user.options, boxes);
                    for (const Bounds3& box : boxes) {
                        part.entries.push_back({o.shape.get(), prim, uint32_t(i), cutsOut, transmits});
                        part.boxes.push_back(
                            namingObject(o, [&] { return toEmbreeBounds(box, m_origin); }));
                    }
                }
            }
        } catch (...) {
            part.error = std::current_exception();
            size_t seen = firstFailed.load(std::memory_order_relaxed);
            while (b < seen && !firstFailed.compare_exchange_weak(seen, b, std::memory_order_relaxed)) {
            }
        }
    });
    size_t total = 0;
    for (const Part& part : parts) {
        if (part.error) std::rethrow_exception(part.error);
        total += part.entries.size();
    }
    m_user.entries.reserve(total);
    m_user.boxes.reserve(total);
    for (const Part& part : parts) {
        m_user.entries.insert(m_user.entries.end(), part.entries.begin(), part.entries.end());
        m_user.boxes.insert(m_user.boxes.end(), part.boxes.begin(), part.boxes.end());
    }
    if (m_user.entries.empty()) return;
    m_userGeomId = attachUserGeometry(m_device, m_scene.get(), m_user, quality);
    if (m_triangleGeoms.size() <= m_userGeomId) m_triangleGeoms.resize(m_userGeomId + 1);
}

void EmbreeAccelerator::addTriangles(const Scene& scene, RTCBuildQuality quality) {
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        const TriangleMesh* mesh = o.shape ? o.shape->nativeTriangles() : nullptr;
        if (!mesh) continue;
        auto g = std::make_unique<EmbreeTriangleGeometry>();
        g->object = uint32_t(i);
        g->filtered = m_filter.filters(uint32_t(i));
        g->cutsOut = m_filter.cutsOut(uint32_t(i));
        g->origin = m_origin;
        namingObject(o, [&] { attachTriangles(m_device, m_scene.get(), *mesh, quality, *g); });
        if (g->geomId == RTC_INVALID_GEOMETRY_ID) continue;  // no triangle with area
        if (m_triangleGeoms.size() <= g->geomId) m_triangleGeoms.resize(g->geomId + 1);
        const unsigned id = g->geomId;
        m_triangleGeoms[id] = std::move(g);
    }
}

namespace {

/// The smallest double that float conversion (round to nearest even) turns
/// into infinity: halfway between FLT_MAX and 2^128. Below it in magnitude a
/// double converts to a finite float.
constexpr double kFloatOverflow = 0x1.ffffffp127;

/// Largest float <= t, for 0 < t <= FLT_MAX: the conversion rounds to
/// nearest, and a result above t is stepped down one ulp (positive floats
/// order like their bit patterns). Equals roundDown(t) without its library call.
inline float floatBelow(double t) {
    float f = static_cast<float>(t);
    if (static_cast<double>(f) > t) {
        uint32_t bits;
        std::memcpy(&bits, &f, sizeof bits);
        --bits;
        std::memcpy(&f, &bits, sizeof f);
    }
    return f;
}

/// (*lo, *hi) from two 8-byte reads (see toEmbreeRay). The empty asm keeps
/// GCC from merging them back into one 16-byte read.
inline __m128d pairOf(const double* lo, const double* hi) {
    __m128d v = _mm_load_sd(lo);
    asm("" : "+x"(v));
    return _mm_loadh_pd(v, hi);
}

}  // namespace

bool EmbreeAccelerator::toEmbreeRay(const Ray& ray, double tMin, double tMax, RTCRay& out) const {
    // Every query pays for this conversion, so it is written with SSE2 (the
    // x86-64 baseline) on the six coordinates in three pairs, (ox, oy),
    // (oz, dx), (dy, dz): each lane is subtracted, compared and rounded to
    // float exactly as the scalar code would (the test compares it with that
    // code), and only the rejecting test branches.
    static_assert(sizeof(Vec3) == 3 * sizeof(double) && offsetof(Ray, d) == sizeof(Vec3),
                  "a ray is six consecutive doubles");
    static_assert(offsetof(RTCRay, org_y) == offsetof(RTCRay, org_x) + sizeof(float) &&
                      offsetof(RTCRay, dir_z) == offsetof(RTCRay, dir_y) + sizeof(float),
                  "Embree's org_x/org_y and dir_y/dir_z are adjacent");
    // The ray is read a double at a time: its caller has usually just
    // written it, and a 16-byte read across two of those stores (or one
    // across half of a store) waits for them to reach the cache, where an
    // 8-byte read within a store is forwarded from it (the profile's
    // hottest instruction of occluded() read (o.z, d.x) at once).
    const __m128d oxy = _mm_sub_pd(pairOf(&ray.o.x, &ray.o.y), _mm_loadu_pd(&m_origin.x));
    const __m128d ozdx = _mm_sub_pd(pairOf(&ray.o.z, &ray.d.x), _mm_set_pd(0.0, m_origin.z));
    const __m128d dyz = pairOf(&ray.d.y, &ray.d.z);
    // One test for everything: a NaN or infinite double, and one beyond
    // float range, would all convert to a non-finite float (|x| < limit is
    // false for NaN).
    const __m128d absMask = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
    const __m128d limit = _mm_set1_pd(kFloatOverflow);
    const __m128d inRange =
        _mm_and_pd(_mm_and_pd(_mm_cmplt_pd(_mm_and_pd(oxy, absMask), limit),
                              _mm_cmplt_pd(_mm_and_pd(ozdx, absMask), limit)),
                   _mm_cmplt_pd(_mm_and_pd(dyz, absMask), limit));
    if (!((_mm_movemask_pd(inRange) == 3) & (tMin < tMax))) return false;
    const __m128 fxy = _mm_cvtpd_ps(oxy);   // (ox, oy, 0, 0), round to nearest
    const __m128 fzx = _mm_cvtpd_ps(ozdx);  // (oz, dx, 0, 0)
    const __m128 fyz = _mm_cvtpd_ps(dyz);   // (dy, dz, 0, 0)
    _mm_storel_pi(reinterpret_cast<__m64*>(&out.org_x), fxy);
    out.org_z = _mm_cvtss_f32(fzx);
    out.dir_x = _mm_cvtss_f32(_mm_shuffle_ps(fzx, fzx, 1));
    _mm_storel_pi(reinterpret_cast<__m64*>(&out.dir_y), fyz);
    // A direction too short for float (or zero) cannot be traced: (dx, dx,
    // dy, dz) all equal to zero (finite here, so no NaN).
    const __m128 dirs = _mm_shuffle_ps(fzx, fyz, _MM_SHUFFLE(1, 0, 1, 1));
    if (_mm_movemask_ps(_mm_cmpeq_ps(dirs, _mm_setzero_ps())) == 0xF) return false;
    // Rounded down so the float interval contains the double one; Embree
    // requires tnear >= 0.
    out.tnear = tMin > 0 ? floatBelow(std::min(tMin, static_cast<double>(FLT_MAX))) : 0.0f;
    out.time = 0;
    // Round-to-nearest is monotonic: t < tMax implies float(t) <= tfar, so the
    // user-geometry callbacks' float check never rejects a hit the double test took.
    out.tfar = toFloat(tMax);
    out.mask = 0xFFFFFFFFu;  // Embree tests masks: an unset mask drops hits silently
    out.id = 0;
    out.flags = 0;
    return true;
}

void EmbreeAccelerator::decode(const RTCRayHit& rayhit, const EmbreeQueryContext& ctx,
                               std::optional<Hit>& out) const {
    const unsigned geomId = rayhit.hit.geomID;
    if (geomId == RTC_INVALID_GEOMETRY_ID) {
        out.reset();
    } else if (geomId == m_userGeomId) {
        // The last user-geometry hit written to Embree's record is the one in
        // the context: a later, closer triangle would have replaced the geomID.
        if (ctx.exactHit) {
            const EmbreeUserTable::Entry& e = m_user.entries[ctx.bestEntry];
            out.emplace(Hit{ctx.bestT, e.object, e.prim, ctx.bestU, ctx.bestV});
        } else {
            const EmbreeUserTable::Entry& e = m_user.entries[rayhit.hit.primID];
            out.emplace(Hit{rayhit.ray.tfar, e.object, e.prim, rayhit.hit.u, rayhit.hit.v});
        }
    } else {
        const EmbreeTriangleGeometry& g = *m_triangleGeoms[geomId];
        out.emplace(Hit{rayhit.ray.tfar, g.object, g.triangle(rayhit.hit.primID), rayhit.hit.u,
                        rayhit.hit.v});
    }
}

std::optional<Hit> EmbreeAccelerator::intersect(const Ray& ray, double tMin, double tMax,
                                                Departure from) const {
    std::optional<Hit> hit;  // the one result: GCC builds it where the caller receives it (NRVO)
    RTCRayHit rayhit;
    if (!toEmbreeRay(ray, tMin, tMax, rayhit.ray)) return hit;
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    EmbreeQueryContext ctx;
    initContext(ctx, &ray, tMin, tMax, from);
    rtcIntersect1(m_scene.get(), &ctx.rtc, &rayhit);
    decode(rayhit, ctx, hit);
    // A triangle hit on (or within float error of) an edge goes to whichever
    // triangle there the naive loop would choose (embree_edge_hits.h).
    if (hit && rayhit.hit.geomID != m_userGeomId && nearTriangleEdge(rayhit.hit.u, rayhit.hit.v))
        hit = resolveEdgeHit(m_edgeHits, ray, tMin, tMax, *hit);
    return hit;
}

namespace {

/// Ray r into lane k of a ray packet (RTCRay8/16: rtcOccluded8/16's input,
/// and the ray half of rtcIntersect8/16's).
template <class RayPacket>
void storeRay(const RTCRay& r, int k, RayPacket& p) {
    p.org_x[k] = r.org_x;
    p.org_y[k] = r.org_y;
    p.org_z[k] = r.org_z;
    p.dir_x[k] = r.dir_x;
    p.dir_y[k] = r.dir_y;
    p.dir_z[k] = r.dir_z;
    p.tnear[k] = r.tnear;
    p.tfar[k] = r.tfar;
    p.time[k] = r.time;
    p.mask[k] = r.mask;
    p.id[k] = r.id;
    p.flags[k] = r.flags;
}

/// Ray r into lane k of a ray/hit packet, with no hit yet (rtcIntersect8/16's input).
template <class Packet>
void storeLane(const RTCRay& r, int k, Packet& p) {
    storeRay(r, k, p.ray);
    p.hit.geomID[k] = p.hit.primID[k] = p.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
}

/// What a lane that is not to be traced holds: besides its 0 in the valid
/// mask, tnear > tfar. A device without a native packet of this width (SSE)
/// hands the packet to its stream path, which ignores the mask and skips
/// exactly such rays (rtcIntersectNM's contract); a zero ray would be traced
/// there, and its callbacks would find no context for the lane.
RTCRay inactiveRay() {
    RTCRay r{};
    r.tnear = 1.0f;
    r.tfar = 0.0f;
    return r;
}

/// Lane k's answer as a single ray's record: the fields decode() reads.
template <class Packet>
RTCRayHit laneAnswer(const Packet& p, int k) {
    RTCRayHit h{};
    h.ray.tfar = p.ray.tfar[k];
    h.hit.u = p.hit.u[k];
    h.hit.v = p.hit.v[k];
    h.hit.primID = p.hit.primID[k];
    h.hit.geomID = p.hit.geomID[k];
    return h;
}

void occludeLanes(const int* valid, RTCScene scene, RTCIntersectContext* ctx, RTCRay8* p) {
    rtcOccluded8(valid, scene, ctx, p);
}
void occludeLanes(const int* valid, RTCScene scene, RTCIntersectContext* ctx, RTCRay16* p) {
    rtcOccluded16(valid, scene, ctx, p);
}

void intersectLanes(const int* valid, RTCScene scene, RTCIntersectContext* ctx, RTCRayHit8* p) {
    rtcIntersect8(valid, scene, ctx, p);
}
void intersectLanes(const int* valid, RTCScene scene, RTCIntersectContext* ctx, RTCRayHit16* p) {
    rtcIntersect16(valid, scene, ctx, p);
}

/// The lane count of an Embree packet type.
template <class Packet>
constexpr int kLanes = 0;
template <>
constexpr int kLanes<RTCRayHit8> = 8;
template <>
constexpr int kLanes<RTCRayHit16> = 16;
template <>
constexpr int kLanes<RTCRay8> = 8;
template <>
constexpr int kLanes<RTCRay16> = 16;

}  // namespace

void EmbreeAccelerator::intersectPacket(const Ray* rays, const double* tMin, const double* tMax,
                                        int count, std::optional<Hit>* out) const {
    static_assert(kPacketRays == 16, "at most one rtcIntersect16 packet");
    if (count < 2 || count > kPacketRays) {
        Accelerator::intersectPacket(rays, tMin, tMax, count, out);
        return;
    }
    if (m_nativePackets16) {
        tracePacket<RTCRayHit16>(rays, tMin, tMax, count, out);
        return;
    }
    // Without AVX-512 Embree would split a 16-wide packet itself (its
    // stream path); two 8-wide packets are its native width.
    for (int i = 0; i < count; i += 8) {
        const int n = std::min(8, count - i);
        if (n == 1)
            out[i] = intersect(rays[i], tMin[i], tMax[i]);
        else
            tracePacket<RTCRayHit8>(rays + i, tMin + i, tMax + i, n, out + i);
    }
}

template <class Packet>
void EmbreeAccelerator::tracePacket(const Ray* rays, const double* tMin, const double* tMax,
                                    int count, std::optional<Hit>* out) const {
    constexpr int K = kLanes<Packet>;
    alignas(64) Packet packet;
    alignas(64) int valid[K];
    EmbreeQueryContext lanes[K];  // init() for traced lanes only: the callbacks reach no other
    for (int k = 0; k < K; ++k) {
        RTCRay r{};
        valid[k] = k < count && toEmbreeRay(rays[k], tMin[k], tMax[k], r) ? -1 : 0;
        if (valid[k] == 0) r = inactiveRay();
        r.id = unsigned(k);  // how the callbacks find the lane's exact context
        storeLane(r, k, packet);
        if (valid[k]) initContext(lanes[k], &rays[k], tMin[k], tMax[k]);
    }
    EmbreeQueryContext ctx;
    initContext(ctx, nullptr, 0, 0);
    ctx.lanes = lanes;
    intersectLanes(valid, m_scene.get(), &ctx.rtc, &packet);
    for (int k = 0; k < count; ++k) {
        if (valid[k] == 0) {
            out[k] = std::nullopt;  // as intersect() answers a ray it cannot trace
            continue;
        }
        // Each lane decoded as a single ray's answer, from its own context,
        // a triangle hit near an edge resolved as intersect() resolves it.
        const RTCRayHit answer = laneAnswer(packet, k);
        decode(answer, lanes[k], out[k]);
        if (out[k] && answer.hit.geomID != m_userGeomId &&
            nearTriangleEdge(answer.hit.u, answer.hit.v))
            out[k] = resolveEdgeHit(m_edgeHits, rays[k], tMin[k], tMax[k], *out[k]);
    }
}

void EmbreeAccelerator::shadowPacket(const Ray* rays, const double* tMin, const double* tMax,
                                     const Departure* from, int count, bool filtered, Color* out,
                                     OcclusionHint* hints) const {
    static_assert(kPacketRays == 16, "at most one rtcOccluded16 packet");
    if (count < 2 || count > kPacketRays) {
        Accelerator::shadowPacket(rays, tMin, tMax, from, count, filtered, out, hints);
        return;
    }
    if (m_nativePackets16) {
        occludePacket<RTCRay16>(rays, tMin, tMax, from, count, filtered, out, hints);
        return;
    }
    for (int i = 0; i < count; i += 8) {
        const int n = std::min(8, count - i);
        OcclusionHint* h = hints ? hints + i : nullptr;
        if (n == 1)
            Accelerator::shadowPacket(rays + i, tMin + i, tMax + i, from + i, 1, filtered, out + i, h);
        else
            occludePacket<RTCRay8>(rays + i, tMin + i, tMax + i, from + i, n, filtered, out + i, h);
    }
}

template <class Packet>
void EmbreeAccelerator::occludePacket(const Ray* rays, const double* tMin, const double* tMax,
                                      const Departure* from, int count, bool filtered, Color* out,
                                      OcclusionHint* hints) const {
    constexpr int K = kLanes<Packet>;
    // transmittance() without an active surface filter is occluded(), the
    // only one that uses hints.
    const bool collect = filtered && m_filter.active();
    if (collect) {
        TransmittanceAccumulator crossings[K];
        occludePacketLanes<Packet>(rays, tMin, tMax, from, count, crossings, out, nullptr);
    } else {
        occludePacketLanes<Packet>(rays, tMin, tMax, from, count, nullptr, out, hints);
    }
}

template <class Packet>
void EmbreeAccelerator::occludePacketLanes(const Ray* rays, const double* tMin,
                                           const double* tMax, const Departure* from, int count,
                                           TransmittanceAccumulator* crossings, Color* out,
                                           OcclusionHint* hints) const {
    constexpr int K = kLanes<Packet>;
    const bool collect = crossings != nullptr;
    alignas(64) Packet packet;
    alignas(64) int valid[K];
    EmbreeQueryContext lanes[K];  // init() for traced lanes only: the callbacks reach no other
    int traced = 0;
    for (int k = 0; k < K; ++k) {
        RTCRay r{};
        valid[k] = 0;
        if (k < count) {
            out[k] = Color(1.0);  // an untraceable feeler is lit, as for one ray
            if (toEmbreeRay(rays[k], tMin[k], tMax[k], r)) {
                OcclusionHint* hint = hints ? &hints[k] : nullptr;
                if (hint && (hint->primitive & hint->fallback) != OcclusionHint::kNone &&
                    answeredByHint(rays[k], tMin[k], tMax[k], from[k], *hint)) {
                    out[k] = Color{};  // its guess blocks it: no walk
                } else {
                    valid[k] = -1;
                    ++traced;
                }
            } else if (hints) {
                hints[k].primitive = OcclusionHint::kNone;
            }
        }
        if (valid[k] == 0) r = inactiveRay();  // answered, or none to trace
        r.id = unsigned(k);  // how the callbacks find the lane's exact context
        storeRay(r, k, packet);
        if (valid[k]) {
            initContext(lanes[k], &rays[k], tMin[k], tMax[k], from[k]);
            if (collect) lanes[k].shadow = &crossings[k];
        }
    }
    if (traced == 0) return;
    EmbreeQueryContext ctx;
    initContext(ctx, nullptr, 0, 0);
    ctx.lanes = lanes;
    occludeLanes(valid, m_scene.get(), &ctx.rtc, &packet);
    for (int k = 0; k < count; ++k) {
        if (valid[k] == 0) continue;
        const bool blocked = packet.tfar[k] < 0.0f;
        // As occluded() leaves the hint: the occluder, or none when lit.
        if (hints) hints[k].primitive = blocked ? lanes[k].occluderEntry : OcclusionHint::kNone;
        if (blocked) {
            out[k] = Color{};
        } else if (collect) {
            m_filter.countCrossings(crossings[k].size());
            out[k] = crossings[k].product();
        }
    }
}

bool EmbreeAccelerator::occluded(const Ray& ray, double tMin, double tMax, Departure from) const {
    RTCRay r;
    if (!toEmbreeRay(ray, tMin, tMax, r)) return false;
    EmbreeQueryContext ctx;
    initContext(ctx, &ray, tMin, tMax, from);
    rtcOccluded1(m_scene.get(), &ctx.rtc, &r);
    return r.tfar < 0.0f;
}

Color EmbreeAccelerator::transmittance(const Ray& ray, double tMin, double tMax,
                                        Departure from) const {
    if (!m_filter.active()) return occluded(ray, tMin, tMax, from) ? Color{} : Color(1.0);
    RTCRay r;
    if (!toEmbreeRay(ray, tMin, tMax, r)) return Color(1.0);
    TransmittanceAccumulator shadow;
    EmbreeQueryContext ctx;
    initContext(ctx, &ray, tMin, tMax, from);
    ctx.shadow = &shadow;
    rtcOccluded1(m_scene.get(), &ctx.rtc, &r);
    // An opaque surface (filtered or not) ended the query; otherwise the
    // filters let every crossing pass and collected it.
    if (r.tfar < 0.0f) return Color{};
    m_filter.countCrossings(shadow.size());
    return shadow.product();
}

void EmbreeAccelerator::initContext(EmbreeQueryContext& ctx, const Ray* ray, double tMin,
                                    double tMax, Departure from) const {
    ctx.init(ray, tMin, tMax, from.object);
    if (m_filter.active()) ctx.filter = &m_filter;
}

bool EmbreeAccelerator::answeredByHint(const Ray& ray, double tMin, double tMax, Departure from,
                                       OcclusionHint& hint) const {
    // Only entries without a cut-out are named (occludedLane): for an opaque
    // feeler their exact test is the whole answer the callback would give. A
    // cut-out would bypass its filter here, so a hint naming one is ignored:
    // the walk asks the filter.
    const auto blocks = [&](uint32_t entry) {
        if (entry >= m_user.entries.size()) return false;
        const EmbreeUserTable::Entry& e = m_user.entries[entry];
        return !e.cutsOut && e.object != from.object &&
               e.shape->occluded(e.prim, ray, tMin, tMax, m_user.options);
    };
    if (blocks(hint.primitive)) return true;
    if (hint.fallback != hint.primitive && blocks(hint.fallback)) {
        hint.primitive = hint.fallback;
        return true;
    }
    return false;
}

bool EmbreeAccelerator::occluded(const Ray& ray, double tMin, double tMax, Departure from,
                                 OcclusionHint& hint) const {
    RTCRay r;
    if (!toEmbreeRay(ray, tMin, tMax, r)) {
        hint.primitive = OcclusionHint::kNone;  // an untraceable feeler is lit
        return false;
    }
    // Most feelers come without a guess (their neighbours were lit): they
    // pay two comparisons, not the guesses' code (out of line).
    if ((hint.primitive & hint.fallback) != OcclusionHint::kNone &&
        answeredByHint(ray, tMin, tMax, from, hint))
        return true;
    EmbreeQueryContext ctx;
    initContext(ctx, &ray, tMin, tMax, from);
    rtcOccluded1(m_scene.get(), &ctx.rtc, &r);
    // A lit point forgets the occluder: its neighbours are likely lit too,
    // and a test of a primitive that does not block is wasted.
    hint.primitive = r.tfar < 0.0f ? ctx.occluderEntry : OcclusionHint::kNone;
    return r.tfar < 0.0f;
}

Color EmbreeAccelerator::transmittance(const Ray& ray, double tMin, double tMax, Departure from,
                                        OcclusionHint& hint) const {
    if (!m_filter.active()) return occluded(ray, tMin, tMax, from, hint) ? Color{} : Color(1.0);
    return transmittance(ray, tMin, tMax, from);
}

std::unique_ptr<Accelerator> makeEmbreeAccelerator(const Scene& scene,
                                                   const AccelOptions& options) {
    return std::make_unique<EmbreeAccelerator>(scene, options);
}

}  // namespace raylab
