#include "renderer/accel/embree_triangles.h"

#include <stdexcept>

#include "renderer/accel/embree_float.h"

namespace raylab {

namespace {

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

/// Filters of meshes the surface filter looks at (cut-outs, transmitters),
/// culling first as above. Intersection: a cut-out candidate is rejected.
/// Occlusion: likewise; in a transmittance query (ctx.shadow) a transmitting
/// candidate is collected and rejected, so traversal goes on behind it, and
/// an opaque one is kept, which ends the query.
template <bool Occlusion>
void filterTriangles(const RTCFilterFunctionNArguments* args) {
    const auto& g = *static_cast<const EmbreeTriangleGeometry*>(args->geometryUserPtr);
    const EmbreeQueryContext& query = *reinterpret_cast<const EmbreeQueryContext*>(args->context);
    const unsigned n = args->N;
    for (unsigned i = 0; i < n; ++i) {
        if (args->valid[i] != -1) continue;
        // A packet's lane has its own exact context (its filter and, for a
        // filtered-shadow feeler, its own crossings), found by the ray's id.
        const EmbreeQueryContext& ctx =
            query.lanes ? query.lanes[RTCRayN_id(args->ray, n, i)] : query;
        const float dx = RTCRayN_dir_x(args->ray, n, i), dy = RTCRayN_dir_y(args->ray, n, i),
                    dz = RTCRayN_dir_z(args->ray, n, i);
        if (g.sides != Sidedness::Both) {
            const float facing = dx * RTCHitN_Ng_x(args->hit, n, i) +
                                 dy * RTCHitN_Ng_y(args->hit, n, i) +
                                 dz * RTCHitN_Ng_z(args->hit, n, i);
            if ((facing < 0) != (g.sides == Sidedness::Outside)) {
                args->valid[i] = 0;
                continue;
            }
        }
        if (!ctx.filter) continue;
        // A transmitter's candidate is a plain hit but in filtered shadows.
        if (!g.cutsOut && !(Occlusion && ctx.shadow)) continue;
        // A single ray's context holds its exact ray (not an 8-wide query's:
        // one context cannot describe its lanes), a lane's context its lane's.
        const Ray ray = (n == 1 || query.lanes) && ctx.ray
                            ? *ctx.ray
                            : Ray{Vec3{RTCRayN_org_x(args->ray, n, i), RTCRayN_org_y(args->ray, n, i),
                                       RTCRayN_org_z(args->ray, n, i)} +
                                      g.origin,
                                  Vec3{dx, dy, dz}};
        // Embree puts the candidate's distance in tfar while the filter runs.
        const Hit candidate{RTCRayN_tfar(args->ray, n, i), g.object,
                            g.triangle(RTCHitN_primID(args->hit, n, i)),
                            RTCHitN_u(args->hit, n, i), RTCHitN_v(args->hit, n, i)};
        if (ctx.filter->cutOut(ray, candidate)) {
            args->valid[i] = 0;
            continue;
        }
        if (Occlusion && ctx.shadow) {
            const Color c = ctx.filter->transmission(ray, candidate);
            if (c.isBlack()) {
                ctx.shadow->block();
            } else {
                ctx.shadow->add(candidate.object, candidate.prim, candidate.t, c);
                args->valid[i] = 0;
            }
        }
    }
}

}  // namespace

void attachTriangles(const EmbreeDevice& device, RTCScene scene, const TriangleMesh& mesh,
                     RTCBuildQuality quality, EmbreeTriangleGeometry& out) {
    if (mesh.triangleCount() == 0) return;
    const Vec3& origin = out.origin;
    const size_t vertexCount = mesh.positions.size();

    EmbreeGeometry geom(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    device.check("rtcNewGeometry(TRIANGLE)");
    // Embree-allocated buffers carry the padding its SIMD loads need; the
    // vertices are converted to float relative to the origin (camera).
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geom.get(), RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertexCount));
    device.check("rtcSetNewGeometryBuffer");

    for (size_t i = 0; i < vertexCount; ++i) {
        const Vec3 p = mesh.positions[i] - origin;
        if (!isFinite(p) || maxComponent(abs(p)) > kMaxEmbreeCoordinate)
            throw std::invalid_argument("vertex " + std::to_string(i) +
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
    device.check("rtcSetNewGeometryBuffer(INDEX)");
    for (size_t j = 0; j < kept.size(); ++j)
        for (int k = 0; k < 3; ++k) indices[3 * j + k] = mesh.triangles[kept[j]][k];
    out.sides = mesh.sidedness();
    if (kept.size() != mesh.triangleCount()) out.triangleOfPrim = std::move(kept);
    if (out.filtered) {
        rtcSetGeometryUserData(geom.get(), &out);
        rtcSetGeometryIntersectFilterFunction(geom.get(), &filterTriangles<false>);
        rtcSetGeometryOccludedFilterFunction(geom.get(), &filterTriangles<true>);
    } else if (out.sides != Sidedness::Both) {
        const RTCFilterFunctionN cull = out.sides == Sidedness::Outside ? &cullTriangleSide<true>
                                                                        : &cullTriangleSide<false>;
        rtcSetGeometryIntersectFilterFunction(geom.get(), cull);
        rtcSetGeometryOccludedFilterFunction(geom.get(), cull);
    }
    rtcSetGeometryBuildQuality(geom.get(), quality);
    rtcCommitGeometry(geom.get());
    device.check("rtcCommitGeometry(TRIANGLE)");
    out.geomId = rtcAttachGeometry(scene, geom.get());
    device.check("rtcAttachGeometry(TRIANGLE)");
}

}  // namespace raylab
