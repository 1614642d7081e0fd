#pragma once
// Indexed triangle mesh in world space, one Shape primitive per triangle
// (double precision; the Embree adaptor uploads it as native float triangles,
// relative to the camera, which the shape declares through nativeTriangles()).
// Embree's barycentric convention p = (1-b1-b2)·p0 + b1·p1 + b2·p2 is shared
// by Embree and the project's own watertight test, so a hit from either
// describes the same point of the same triangle.
//
// Surface parameters: the file's texture coordinates when the mesh has them,
// otherwise pbrt's default per-triangle (0,0), (1,0), (1,1), i.e.
// uv = (b1 + b2, b2). dpdu/dpdv solve p - p2 = (uv - uv2)·[dpdu dpdv] over the
// triangle; dndu/dndv are the derivatives of the normalised interpolated
// vertex normal (zero for a flat triangle). Vertex colours, when the mesh has
// them, are interpolated like the normals into the surface record's colour.

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/shape.h"
#include "geometry/vec.h"
#include "geometry/vec2.h"

namespace raylab {

class TriangleMesh final : public Shape {
public:
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  ///< per-vertex, same size as positions, or empty
    std::vector<Vec2> uvs;      ///< per-vertex texture coordinates, same size, or empty
    std::vector<Vec3> colors;   ///< per-vertex colour (OBJ "v x y z r g b"), same size, or empty
    std::vector<std::array<uint32_t, 3>> triangles;

    TriangleMesh() { m_sides = Sidedness::Both; }

    bool hasNormals() const { return !normals.empty(); }
    bool hasUvs() const { return !uvs.empty(); }
    bool hasColors() const { return !colors.empty(); }
    size_t triangleCount() const { return triangles.size(); }

    uint32_t primitiveCount() const override { return uint32_t(triangles.size()); }
    Bounds3 bounds() const override;
    Bounds3 bounds(uint32_t prim) const override;

    /// The watertight test (geometry/triangle.h), with the mesh's sidedness.
    std::optional<ShapeHit> intersect(uint32_t prim, const Ray& ray, double tMin, double tMax,
                                      const IntersectOptions& opt) const override;
    /// One loop over every triangle with the watertight test's per-ray
    /// constants computed once (the naive accelerator's inner loop).
    std::optional<PrimitiveHit> intersectAny(const Ray& ray, double tMin, double tMax,
                                             const IntersectOptions& opt) const override;
    bool occludedAny(const Ray& ray, double tMin, double tMax,
                     const IntersectOptions& opt) const override;

    /// Surface data recomputed in double from the ray and the triangle alone
    /// (the hit's t and barycentrics are only a fallback): every accelerator
    /// that picks this triangle, in float or double, gets bit-identical data.
    SurfaceGeometry surfaceAt(uint32_t prim, const Ray& ray, const ShapeHit& hit,
                              const IntersectOptions& opt, SurfaceDetail detail) const override;

    const char* kind() const override { return "triangle mesh"; }
    /// Every index within positions, normals and uvs sized like positions.
    void validate() const override;
    const TriangleMesh* nativeTriangles() const override { return this; }
    bool hasShadingNormals() const override { return hasNormals(); }

private:
    /// Whether a hit from direction d on triangle `prim` is on an accepted side.
    bool acceptsFacing(uint32_t prim, const Vec3& d) const;
};

}  // namespace raylab
