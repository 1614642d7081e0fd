#pragma once
// Triangle hits on a shared edge, decided the way the naive loop decides them.
//
// Embree tests triangles in float; the naive loop (and Scene::surfaceAt) in
// double with the watertight test. A ray through an edge shared by two
// triangles - the seam between two tiles of a checkerboard - may be given to
// one triangle by Embree and to its neighbour by the double test, and the two
// may carry different materials. Such a hit is recognisable: Embree's float
// barycentrics put it within a hair of an edge. For those hits (about 1 in
// 1000 triangle hits; the others cannot change owner) the triangles around
// the hit point are found with an Embree point query and run through the
// naive loop's own per-primitive test, in the naive loop's order, so the
// closest double hit wins and an exact tie goes to the earlier object and
// triangle: the naive loop's answer. Internal to renderer/accel.

#include <embree3/rtcore.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/ray.h"
#include "renderer/accel/embree_triangles.h"
#include "renderer/accel/hit.h"
#include "renderer/scene.h"
#include "renderer/surface_filter.h"

namespace raylab {

/// \brief Float barycentrics (Embree's u, v) nearer than this to an edge send
///   a hit to resolveEdgeHit.
/// \details Embree's barycentrics are off by about 6e-8 × (distance from the
///   accelerator origin) / (triangle size); 1e-3 covers that for triangles a
///   thousandth of their distance across with a margin of 16, and costs a
///   point query on well under 1% of triangle hits.
constexpr float kEdgeBand = 1e-3f;

/// Whether Embree's hit at barycentrics (u, v) is within kEdgeBand of an edge.
inline bool nearTriangleEdge(float u, float v) {
    return (u < kEdgeBand) | (v < kEdgeBand) | (1.0f - u - v < kEdgeBand);
}

/// What resolveEdgeHit needs of the accelerator: its Embree scene and tables.
struct EdgeHitContext {
    RTCScene scene = nullptr;
    Vec3 origin;                        ///< Embree's coordinates are relative to it
    unsigned userGeomId = RTC_INVALID_GEOMETRY_ID;
    const std::vector<std::unique_ptr<EmbreeTriangleGeometry>>* triangleGeoms = nullptr;
    const std::vector<const Shape*>* shapes = nullptr;  ///< Scene::objects' shapes
    const SurfaceFilter* filter = nullptr;
    IntersectOptions options;
};

/// \brief The naive loop's choice among the triangles around Embree's hit
///   `hit` (a triangle hit of `ray` in (tMin, tMax)), or `hit` itself when it
///   is that choice or when no triangle there is hit in double (then
///   Scene::surfaceAt clamps the hit to Embree's triangle, as before).
Hit resolveEdgeHit(const EdgeHitContext& ctx, const Ray& ray, double tMin, double tMax,
                   const Hit& hit);

}  // namespace raylab
