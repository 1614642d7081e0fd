#include "renderer/accel/embree_accelerator.h"

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "renderer/accel/embree_factory.h"
#include "renderer/timing.h"

namespace raylab {

// The callbacks recover the extended context from Embree's pointer to its
// first member; that cast is only valid for a standard-layout struct.
static_assert(std::is_standard_layout<EmbreeQueryContext>::value,
              "EmbreeQueryContext must be standard-layout");
static_assert(offsetof(EmbreeQueryContext, rtc) == 0, "rtc must be the first member");

namespace {

constexpr float kInfF = std::numeric_limits<float>::infinity();

/// Embree silently drops boxes beyond ±FLT_LARGE (1.844e18, NUMERICS.md §1);
/// infinite extents are clamped to this, which is still "everywhere" for any
/// ray a float BVH can trace.
constexpr double kMaxCoordinate = 1e18;

/// User-geometry boxes are traversed with the non-robust slab test even under
/// RTC_SCENE_FLAG_ROBUST: pad them by ~1e-6 of their largest coordinate.
constexpr double kBoxPadding = 8.0 * FLT_EPSILON;

/// Largest float <= x (x finite and within float range).
float roundDown(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -kInfF);
    return f;
}

/// Smallest float >= x (x finite and within float range).
float roundUp(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, kInfF);
    return f;
}

/// double -> float without the undefined behaviour of converting an
/// out-of-range value: beyond ±FLT_MAX the result is ±inf.
float toFloat(double x) {
    if (x > static_cast<double>(FLT_MAX)) return kInfF;
    if (x < -static_cast<double>(FLT_MAX)) return -kInfF;
    return static_cast<float>(x);
}

Vec3 clampCoordinates(const Vec3& p) {
    const auto c = [](double x) { return std::clamp(x, -kMaxCoordinate, kMaxCoordinate); };
    return {c(p.x), c(p.y), c(p.z)};
}

/// The Embree box of a shape: relative to `origin`, clamped to the range
/// Embree accepts, padded, and rounded outward to float.
RTCBounds toEmbreeBounds(const Bounds3& world, const Vec3& origin, const Object& object) {
    RTCBounds out{};
    if (std::isnan(world.lo.x) || std::isnan(world.lo.y) || std::isnan(world.lo.z) ||
        std::isnan(world.hi.x) || std::isnan(world.hi.y) || std::isnan(world.hi.z)) {
        throw std::invalid_argument("embree: object '" + object.name + "' (" +
                                    object.shape->kind() + ") has NaN bounds");
    }
    if (world.empty()) {
        // Embree ignores a primitive whose box has lower > upper.
        out.lower_x = out.lower_y = out.lower_z = 1.0f;
        out.upper_x = out.upper_y = out.upper_z = -1.0f;
        return out;
    }
    Bounds3 rel;
    rel.lo = clampCoordinates(world.lo - origin);
    rel.hi = clampCoordinates(world.hi - origin);
    rel = rel.padded(kBoxPadding);
    rel.lo = clampCoordinates(rel.lo);
    rel.hi = clampCoordinates(rel.hi);
    out.lower_x = roundDown(rel.lo.x);
    out.lower_y = roundDown(rel.lo.y);
    out.lower_z = roundDown(rel.lo.z);
    out.upper_x = roundUp(rel.hi.x);
    out.upper_y = roundUp(rel.hi.y);
    out.upper_z = roundUp(rel.hi.z);
    return out;
}

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

// ---------------------------------------------------------------------------
// Generic user-geometry callbacks (one set for every analytic shape kind).

using AnalyticTable = EmbreeAccelerator::AnalyticTable;

const AnalyticTable& tableOf(void* geometryUserPtr) {
    return *static_cast<const AnalyticTable*>(geometryUserPtr);
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

void boundsCallback(const RTCBoundsFunctionArguments* args) {
    // Computed from Shape::bounds() once at build time (where bad bounds can
    // still throw); the userPtr argument of rtcSetGeometryBoundsFunction is
    // ignored by Embree 3.13.5, so the table comes from geometryUserPtr.
    *args->bounds_o = tableOf(args->geometryUserPtr).boxes[args->primID];
}

void intersectCallback(const RTCIntersectFunctionNArguments* args) {
    const AnalyticTable& table = tableOf(args->geometryUserPtr);
    EmbreeQueryContext& ctx = contextOf(args->context);
    const unsigned n = args->N;
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, n);
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, n);
    const Shape& shape = *table.shapes[args->primID];
    // Single-ray queries from EmbreeAccelerator carry the exact double ray, so
    // the shape computes the same t, u, v as in the naive loop.
    const bool exact = n == 1 && ctx.ray != nullptr;

    for (unsigned i = 0; i < n; ++i) {
        if (args->valid[i] != -1) continue;
        float& tfar = RTCRayN_tfar(rays, n, i);
        const uint32_t object = table.objects[args->primID];
        std::optional<ShapeHit> h;
        if (exact) {
            // Strict tMin < t < best-so-far in double (Shape contract). Exact
            // ties (coplanar surfaces, e.g. a cone's cap on the floor) go to
            // the lower object index, as in the naive loop, which visits
            // objects in order: so the limit is opened by one ulp for a
            // lower-indexed object and the tie is settled here.
            const bool winsTies = ctx.exactHit && object < ctx.bestObject;
            const double tMax = winsTies ? std::nextafter(ctx.bestT, std::numeric_limits<double>::infinity()) : ctx.bestT;
            h = shape.intersect(*ctx.ray, ctx.tMin, tMax);
            if (h && !(h->t < ctx.bestT || (winsTies && h->t == ctx.bestT))) continue;
        } else {
            h = shape.intersect(laneRay(rays, n, i, table.origin), RTCRayN_tnear(rays, n, i), tfar);
        }
        if (!h) continue;
        // A triangle may already have shrunk tfar below this (double) hit.
        const float t = static_cast<float>(h->t);
        if (!(t <= tfar)) continue;

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
        if (exact) {
            ctx.bestT = h->t;
            ctx.bestU = h->u;
            ctx.bestV = h->v;
            ctx.bestObject = object;
            ctx.exactHit = true;
        }
    }
}

void occludedCallback(const RTCOccludedFunctionNArguments* args) {
    const AnalyticTable& table = tableOf(args->geometryUserPtr);
    const EmbreeQueryContext& ctx = contextOf(args->context);
    const unsigned n = args->N;
    RTCRayN* rays = args->ray;
    const Shape& shape = *table.shapes[args->primID];
    const bool exact = n == 1 && ctx.ray != nullptr;

    for (unsigned i = 0; i < n; ++i) {
        if (args->valid[i] != -1) continue;
        float& tfar = RTCRayN_tfar(rays, n, i);
        const bool hit = exact ? shape.occluded(*ctx.ray, ctx.tMin, ctx.bestT)
                               : shape.occluded(laneRay(rays, n, i, table.origin),
                                                RTCRayN_tnear(rays, n, i), tfar);
        if (hit) tfar = -kInfF;  // Embree's "occluded" marker
    }
}

/// Filters of one-sided triangle meshes. Embree's triangle Ng is
/// (v1 - v0) × (v2 - v0), so a hit is on the front (counter-clockwise) side
/// when dot(d, Ng) < 0; a hit on the culled side is rejected (valid = 0) and
/// traversal continues behind it.
template <bool KeepFront>
void cullTriangleSide(const RTCFilterFunctionNArguments* args) {
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const float facing = RTCRayN_dir_x(args->ray, args->N, i) * RTCHitN_Ng_x(args->hit, args->N, i) +
                             RTCRayN_dir_y(args->ray, args->N, i) * RTCHitN_Ng_y(args->hit, args->N, i) +
                             RTCRayN_dir_z(args->ray, args->N, i) * RTCHitN_Ng_z(args->hit, args->N, i);
        if ((facing < 0) != KeepFront) args->valid[i] = 0;
    }
}

}  // namespace

// ---------------------------------------------------------------------------

EmbreeAccelerator::EmbreeAccelerator(const Scene& scene, const AccelOptions& options,
                                     const std::string& deviceConfig)
    : m_device(deviceConfig), m_origin(options.origin), m_scene(m_device) {
    m_device.check("rtcNewScene");
    if (!isFinite(m_origin))
        throw std::invalid_argument("embree: accelerator origin must be finite");
    const auto start = std::chrono::steady_clock::now();

    const RTCBuildQuality quality = toEmbree(options.quality);
    rtcSetSceneFlags(m_scene.get(), options.robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
    rtcSetSceneBuildQuality(m_scene.get(), quality);
    m_device.check("scene setup");

    addAnalyticShapes(scene, quality);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        if (o.isMesh()) addMesh(o, static_cast<uint32_t>(i), quality);
    }

    rtcCommitScene(m_scene.get());
    m_device.check("rtcCommitScene");
    m_buildSeconds =
        secondsSince(start);
}

void EmbreeAccelerator::addAnalyticShapes(const Scene& scene, RTCBuildQuality quality) {
    m_analytic.origin = m_origin;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        if (o.isMesh() || !o.shape) continue;
        m_analytic.shapes.push_back(o.shape.get());
        m_analytic.objects.push_back(static_cast<uint32_t>(i));
        m_analytic.boxes.push_back(toEmbreeBounds(o.shape->bounds(), m_origin, o));
    }
    if (m_analytic.shapes.empty()) return;

    // Creation order from NUMERICS.md §1: count, user data, callbacks, commit, attach.
    EmbreeGeometry geom(m_device, RTC_GEOMETRY_TYPE_USER);
    m_device.check("rtcNewGeometry(USER)");
    rtcSetGeometryUserPrimitiveCount(geom.get(), static_cast<unsigned>(m_analytic.shapes.size()));
    rtcSetGeometryUserData(geom.get(), &m_analytic);
    rtcSetGeometryBoundsFunction(geom.get(), &boundsCallback, nullptr);
    rtcSetGeometryIntersectFunction(geom.get(), &intersectCallback);
    rtcSetGeometryOccludedFunction(geom.get(), &occludedCallback);
    rtcSetGeometryBuildQuality(geom.get(), quality);
    rtcCommitGeometry(geom.get());
    m_device.check("user geometry setup");
    m_userGeomId = rtcAttachGeometry(m_scene.get(), geom.get());
    m_device.check("rtcAttachGeometry(USER)");
    if (m_objectOfGeom.size() <= m_userGeomId) {
        m_objectOfGeom.resize(m_userGeomId + 1, 0);
        m_triangleOfPrim.resize(m_userGeomId + 1);
    }
    // geom's destructor releases our reference; the scene keeps its own.
}

void EmbreeAccelerator::addMesh(const Object& object, uint32_t objectIndex,
                                RTCBuildQuality quality) {
    const TriangleMesh& mesh = *object.mesh;
    if (mesh.triangleCount() == 0) return;
    const size_t vertexCount = mesh.positions.size();

    EmbreeGeometry geom(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
    m_device.check("rtcNewGeometry(TRIANGLE)");
    // Embree-allocated buffers carry the padding its SIMD loads need; the
    // vertices are converted to float relative to the origin (camera).
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geom.get(), RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertexCount));
    m_device.check("rtcSetNewGeometryBuffer");

    for (size_t i = 0; i < vertexCount; ++i) {
        const Vec3 p = mesh.positions[i] - m_origin;
        if (!isFinite(p) || maxComponent(abs(p)) > kMaxCoordinate)
            throw std::invalid_argument("embree: mesh '" + object.name + "': vertex " +
                                        std::to_string(i) +
                                        " is not finite or too far from the origin");
        vertices[3 * i + 0] = static_cast<float>(p.x);
        vertices[3 * i + 1] = static_cast<float>(p.y);
        vertices[3 * i + 2] = static_cast<float>(p.z);
    }
    // Triangles whose float vertices are collinear have no area but Embree's
    // robust mode still reports hits on them at their vertices (measured:
    // ~10% of rays aimed exactly at such a vertex): they are left out, and
    // Embree's primID is mapped back to the mesh's triangle index.
    std::vector<uint32_t> kept;
    kept.reserve(mesh.triangleCount());
    auto floatVertex = [&](uint32_t i) {
        return Vec3{vertices[3 * i + 0], vertices[3 * i + 1], vertices[3 * i + 2]};
    };
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t index = mesh.triangles[t][k];
            // Embree does not check indices; an out-of-range one would read garbage.
            if (index >= vertexCount)
                throw std::invalid_argument(
                    "embree: mesh '" + object.name + "': triangle " + std::to_string(t) +
                    " uses vertex " + std::to_string(index) + " of " + std::to_string(vertexCount));
        }
        const auto& tri = mesh.triangles[t];
        const Vec3 a = floatVertex(tri[0]);
        // Differences of floats are exact in double when the exponents are
        // close, and the cross product then decides collinearity reliably.
        if (lengthSquared(cross(floatVertex(tri[1]) - a, floatVertex(tri[2]) - a)) > 0)
            kept.push_back(uint32_t(t));
    }
    if (kept.empty()) return;
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geom.get(), RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), kept.size()));
    m_device.check("rtcSetNewGeometryBuffer(INDEX)");
    for (size_t j = 0; j < kept.size(); ++j)
        for (int k = 0; k < 3; ++k) indices[3 * j + k] = mesh.triangles[kept[j]][k];
    if (object.meshSides != Sidedness::Both) {
        const RTCFilterFunctionN cull = object.meshSides == Sidedness::Outside
                                            ? &cullTriangleSide<true>
                                            : &cullTriangleSide<false>;
        rtcSetGeometryIntersectFilterFunction(geom.get(), cull);
        rtcSetGeometryOccludedFilterFunction(geom.get(), cull);
    }
    rtcSetGeometryBuildQuality(geom.get(), quality);
    rtcCommitGeometry(geom.get());
    m_device.check("rtcCommitGeometry(TRIANGLE)");
    const unsigned geomId = rtcAttachGeometry(m_scene.get(), geom.get());
    m_device.check("rtcAttachGeometry(TRIANGLE)");
    if (m_objectOfGeom.size() <= geomId) {
        m_objectOfGeom.resize(geomId + 1, 0);
        m_triangleOfPrim.resize(geomId + 1);
    }
    m_objectOfGeom[geomId] = objectIndex;
    if (kept.size() != mesh.triangleCount()) m_triangleOfPrim[geomId] = std::move(kept);
}

bool EmbreeAccelerator::toEmbreeRay(const Ray& ray, double tMin, double tMax, RTCRay& out) const {
    if (!(tMin < tMax)) return false;
    const Vec3 o = ray.o - m_origin;
    const Vec3f of{toFloat(o.x), toFloat(o.y), toFloat(o.z)};
    const Vec3f df{toFloat(ray.d.x), toFloat(ray.d.y), toFloat(ray.d.z)};
    // One test for everything: a NaN or infinite double, and one beyond
    // float range, all convert to a non-finite float.
    if (!isFinite(of) || !isFinite(df) || df == Vec3f{0, 0, 0}) return false;

    out.org_x = of.x;
    out.org_y = of.y;
    out.org_z = of.z;
    // Rounded down so the float interval contains the double one; Embree
    // requires tnear >= 0.
    out.tnear = tMin > 0 ? roundDown(std::min(tMin, static_cast<double>(FLT_MAX))) : 0.0f;
    out.dir_x = df.x;
    out.dir_y = df.y;
    out.dir_z = df.z;
    out.time = 0;
    // Round-to-nearest is monotonic: t < tMax implies float(t) <= tfar, so the
    // analytic callbacks' float check never rejects a hit the double test took.
    out.tfar = toFloat(tMax);
    out.mask = 0xFFFFFFFFu;  // Embree tests masks: an unset mask drops hits silently
    out.id = 0;
    out.flags = 0;
    return true;
}

void EmbreeAccelerator::initContext(EmbreeQueryContext& ctx, const Ray* ray, double tMin,
                                    double tMax) {
    rtcInitIntersectContext(&ctx.rtc);
    ctx.ray = ray;
    ctx.tMin = tMin;
    ctx.bestT = tMax;
    ctx.bestU = ctx.bestV = 0;
    ctx.bestObject = 0;
    ctx.exactHit = false;
}

std::optional<Hit> EmbreeAccelerator::decode(const RTCRayHit& rayhit,
                                             const EmbreeQueryContext& ctx) const {
    const unsigned geomId = rayhit.hit.geomID;
    if (geomId == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    if (geomId == m_userGeomId) {
        // The last analytic hit written to Embree's record is the one in the
        // context: a later, closer triangle would have replaced the geomID.
        if (ctx.exactHit) return Hit{ctx.bestT, ctx.bestObject, 0, ctx.bestU, ctx.bestV};
        return Hit{rayhit.ray.tfar, m_analytic.objects[rayhit.hit.primID], 0, rayhit.hit.u,
                   rayhit.hit.v};
    }
    const std::vector<uint32_t>& remap = m_triangleOfPrim[geomId];
    const uint32_t triangle = remap.empty() ? rayhit.hit.primID : remap[rayhit.hit.primID];
    return Hit{rayhit.ray.tfar, m_objectOfGeom[geomId], triangle, rayhit.hit.u,
               rayhit.hit.v};
}

std::optional<Hit> EmbreeAccelerator::intersect(const Ray& ray, double tMin, double tMax) const {
    RTCRayHit rayhit;
    if (!toEmbreeRay(ray, tMin, tMax, rayhit.ray)) return std::nullopt;
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    EmbreeQueryContext ctx;
    initContext(ctx, &ray, tMin, tMax);
    rtcIntersect1(m_scene.get(), &ctx.rtc, &rayhit);
    return decode(rayhit, ctx);
}

bool EmbreeAccelerator::occluded(const Ray& ray, double tMin, double tMax) const {
    RTCRay r;
    if (!toEmbreeRay(ray, tMin, tMax, r)) return false;
    EmbreeQueryContext ctx;
    initContext(ctx, &ray, tMin, tMax);
    rtcOccluded1(m_scene.get(), &ctx.rtc, &r);
    return r.tfar < 0.0f;
}

std::unique_ptr<Accelerator> makeEmbreeAccelerator(const Scene& scene,
                                                   const AccelOptions& options) {
    return std::make_unique<EmbreeAccelerator>(scene, options);
}

}  // namespace raylab
