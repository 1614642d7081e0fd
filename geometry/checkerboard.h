#pragma once
// A procedural checkerboard: a parallelogram split into squares, two
// triangles each, for floors (the JSON "checkerboard" object).

#include "geometry/triangle_mesh.h"
#include "geometry/vec.h"

namespace raylab {

/// The parallelogram origin + s·edgeU + t·edgeV (s, t in [0, 1]) as an
/// (nu+1) x (nv+1) grid of shared vertices; square (i, j), i along edgeU,
/// becomes triangles 2k and 2k + 1 with k = j·nu + i, wound so that their
/// normal is edgeU × edgeV. Requires nu, nv >= 1.
TriangleMesh makeCheckerboard(const Vec3& origin, const Vec3& edgeU, const Vec3& edgeV, int nu,
                              int nv);

}  // namespace raylab
