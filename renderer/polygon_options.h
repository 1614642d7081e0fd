#pragma once
// `raylab render --polygons triangles`: planar polygons become Embree
// triangles, so they can be compared in speed and image with the analytic
// polygons' two inside tests (IntersectOptions::polygonTest).

#include <string>

#include "geometry/primitives.h"
#include "renderer/scene.h"

namespace raylab {

/// Replaces every analytic polygon by triangles (ear clipping of its vertices,
/// wound like the polygon, per-vertex normals kept), gathered into one
/// triangle mesh with per-face materials. Triangles are hit from both sides,
/// and self-intersecting polygons (whose fill depends on the even-odd or
/// nonzero rule) are triangulated as if simple. Returns the number of
/// polygons replaced.
size_t triangulatePolygons(Scene& scene);

}  // namespace raylab
