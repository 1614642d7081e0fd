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

}  // namespace

std::optional<EmbreeTriangleGeometry> attachTriangles(const EmbreeDevice& device, RTCScene scene,
                                                      const TriangleMesh& mesh, const Vec3& origin,
                                                      RTCBuildQuality quality) {
    if (mesh.triangleCount() == 0) return std::nullopt;
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
    if (kept.empty()) return std::nullopt;
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geom.get(), RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), kept.size()));
    device.check("rtcSetNewGeometryBuffer(INDEX)");
    for (size_t j = 0; j < kept.size(); ++j)
        for (int k = 0; k < 3; ++k) indices[3 * j + k] = mesh.triangles[kept[j]][k];
    if (mesh.sidedness() != Sidedness::Both) {
        const RTCFilterFunctionN cull = mesh.sidedness() == Sidedness::Outside
                                            ? &cullTriangleSide<true>
                                            : &cullTriangleSide<false>;
        rtcSetGeometryIntersectFilterFunction(geom.get(), cull);
        rtcSetGeometryOccludedFilterFunction(geom.get(), cull);
    }
    rtcSetGeometryBuildQuality(geom.get(), quality);
    rtcCommitGeometry(geom.get());
    device.check("rtcCommitGeometry(TRIANGLE)");
    EmbreeTriangleGeometry out;
    out.geomId = rtcAttachGeometry(scene, geom.get());
    device.check("rtcAttachGeometry(TRIANGLE)");
    if (kept.size() != mesh.triangleCount()) out.triangleOfPrim = std::move(kept);
    return out;
}

}  // namespace raylab
