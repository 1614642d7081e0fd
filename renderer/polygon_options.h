#pragma once
// Scene-wide choices for planar polygons, applied after loading: which inside
// test the analytic polygons use, or whether they become Embree triangles, so
// the three can be compared in speed and image (raylab render --polygons).

#include <string>

#include "geometry/primitives.h"
#include "renderer/scene.h"

namespace raylab {

/// Switches every analytic polygon to `test`.
void setPolygonInsideTest(Scene& scene, PolygonTest test);

/// Replaces every analytic polygon by triangles (ear clipping of its vertices,
/// wound like the polygon, per-vertex normals kept), gathered into one
/// triangle mesh with per-face materials. Triangles are hit from both sides,
/// and self-intersecting polygons (whose fill depends on the even-odd or
/// nonzero rule) are triangulated as if simple. Returns the number of
/// polygons replaced.
size_t triangulatePolygons(Scene& scene);

}  // namespace raylab
