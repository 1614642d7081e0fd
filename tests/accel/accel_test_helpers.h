#pragma once
// Scene builders and a deterministic generator shared by the accelerator
// tests. Scenes are built in code: analytic shapes from geometry/primitives.h,
// meshes assembled here.

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "geometry/analytic_shape.h"
#include "geometry/primitives.h"
#include "geometry/random.h"
#include "geometry/shape.h"
#include "geometry/triangle_mesh.h"
#include "renderer/scene.h"
#include "shape_queries.h"

namespace raylab::accel_test {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

/// Deterministic test rays and points (geometry/random.h).
using Rng = SplitMix64;

/// Object wrapping an analytic shape.
inline Object shapeObject(std::string name, std::unique_ptr<Shape> shape, uint32_t material = 0) {
    Object o;
    o.name = std::move(name);
    o.shape = std::move(shape);
    o.material = material;
    return o;
}

/// Object wrapping a mesh.
inline Object meshObject(std::string name, std::shared_ptr<TriangleMesh> mesh,
                         uint32_t material = 0) {
    Object o;
    o.name = std::move(name);
    o.shape = std::move(mesh);
    o.material = material;
    return o;
}

/// Axis-aligned square [x0,x1] × [y0,y1] at height z as two triangles
/// (0,1,2), (0,2,3), counter-clockwise seen from +z (normal +z).
inline std::shared_ptr<TriangleMesh> quadMesh(double x0, double y0, double x1, double y1,
                                              double z) {
    auto m = std::make_shared<TriangleMesh>();
    m->positions = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
    m->triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

/// Closed latitude/longitude sphere mesh (poles shared), outward winding,
/// with per-vertex normals when `normals` is set.
inline std::shared_ptr<TriangleMesh> uvSphereMesh(const Vec3& centre, double radius, int rings,
                                                  int segments, bool normals) {
    auto m = std::make_shared<TriangleMesh>();
    m->positions.push_back(centre + Vec3{0, 0, radius});  // north pole, index 0
    for (int i = 1; i < rings; ++i) {
        const double theta = kPi * i / rings;
        for (int j = 0; j < segments; ++j) {
            const double phi = 2 * kPi * j / segments;
            m->positions.push_back(centre + Vec3{std::sin(theta) * std::cos(phi),
                                                 std::sin(theta) * std::sin(phi), std::cos(theta)} *
                                                radius);
        }
    }
    m->positions.push_back(centre - Vec3{0, 0, radius});  // south pole
    const auto south = static_cast<uint32_t>(m->positions.size() - 1);
    const auto ring = [&](int i, int j) {
        return static_cast<uint32_t>(1 + (i - 1) * segments + (j % segments));
    };
    for (int j = 0; j < segments; ++j) {
        m->triangles.push_back({0, ring(1, j), ring(1, j + 1)});
        for (int i = 1; i + 1 < rings; ++i) {
            m->triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            m->triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
        m->triangles.push_back({ring(rings - 1, j), south, ring(rings - 1, j + 1)});
    }
    if (normals)
        for (const Vec3& p : m->positions) m->normals.push_back(normalize(p - centre));
    return m;
}

/// Random height-field grid over [-s, s]² at height ~z (n×n quads).
inline std::shared_ptr<TriangleMesh> terrainMesh(Rng& rng, double s, double z, int n) {
    auto m = std::make_shared<TriangleMesh>();
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            m->positions.push_back(
                {-s + 2 * s * i / n, -s + 2 * s * j / n, z + rng.uniform(-0.5, 0.5)});
    const auto at = [n](int i, int j) { return static_cast<uint32_t>(i * (n + 1) + j); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            m->triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m->triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return m;
}

/// A mixed scene: `spheres` random analytic spheres in [-10, 10]³, a mesh
/// sphere with normals, a terrain mesh below and a finite ground plane below
/// that; everything shifted by `offset`.
inline Scene randomScene(uint64_t seed, int spheres, const Vec3& offset = {0, 0, 0}) {
    Rng rng(seed);
    Scene scene;
    scene.materials.resize(4);
    for (int i = 0; i < spheres; ++i)
        scene.objects.push_back(
            shapeObject("sphere" + std::to_string(i),
                        makeSphere(offset + rng.point(-10, 10), rng.uniform(0.2, 1.5)),
                        static_cast<uint32_t>(i % 4)));
    scene.objects.push_back(
        meshObject("ball", uvSphereMesh(offset + Vec3{2, -3, 1}, 3, 24, 48, true), 1));
    auto terrain = terrainMesh(rng, 14, -11, 24);
    for (Vec3& p : terrain->positions) p += offset;
    scene.objects.push_back(meshObject("terrain", terrain, 2));
    scene.objects.push_back(
        shapeObject("ground", makePlane(offset + Vec3{0, 0, -13}, {0, 0, 1}, 40), 3));
    return scene;
}

/// A test-only analytic shape: the plane z = height, hit from either side,
/// with INFINITE bounds (what an unclipped plane would report). Embree drops
/// such boxes silently; the accelerator must clamp them.
class UnboundedPlaneZ final : public AnalyticShape<UnboundedPlaneZ> {
public:
    explicit UnboundedPlaneZ(double height) : m_height(height) { m_sides = Sidedness::Both; }
    Bounds3 bounds() const override {
        Bounds3 b;
        b.lo = {-kInf, -kInf, m_height};
        b.hi = {kInf, kInf, m_height};
        return b;
    }
    template <class T>
    std::optional<ShapeHit> intersectT(const Ray& ray, double tMin, double tMax,
                                       const IntersectOptions&) const {
        const double t = (m_height - ray.o.z) / ray.d.z;
        if (!(t > tMin && t < tMax)) return std::nullopt;
        const Vec3 p = ray.at(t);
        return ShapeHit{t, p.x, p.y};
    }
    SurfaceGeometry surface(const Ray& ray, const ShapeHit& hit, SurfaceDetail) const {
        SurfaceGeometry g;
        g.p = {hit.u, hit.v, m_height};
        g.ng = g.ns = {0, 0, 1};
        g.frontFace = ray.d.z < 0;
        return g;
    }
    const char* kind() const override { return "unbounded-plane"; }

private:
    double m_height;
};

/// A test-only shape whose bounds are NaN (a broken primitive).
class NanBoundsShape final : public AnalyticShape<NanBoundsShape> {
public:
    Bounds3 bounds() const override {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        Bounds3 b;
        b.lo = {nan, 0, 0};
        b.hi = {1, 1, 1};
        return b;
    }
    template <class T>
    std::optional<ShapeHit> intersectT(const Ray&, double, double, const IntersectOptions&) const {
        return std::nullopt;
    }
    SurfaceGeometry surface(const Ray&, const ShapeHit&, SurfaceDetail) const { return {}; }
    const char* kind() const override { return "nan-bounds"; }
};

}  // namespace raylab::accel_test
