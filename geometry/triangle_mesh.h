#pragma once
// Indexed triangle mesh in world space (double precision; the Embree adaptor
// converts to float relative to the camera). Embree's barycentric convention:
// p = (1-u-v)·p0 + u·p1 + v·p2, shared by Embree and the project's own test.

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/bounds.h"
#include "geometry/vec.h"

namespace raylab {

struct TriangleMesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  ///< per-vertex, same size as positions, or empty
    std::vector<std::array<uint32_t, 3>> triangles;

    bool hasNormals() const { return !normals.empty(); }
    size_t triangleCount() const { return triangles.size(); }

    Bounds3 bounds() const {
        Bounds3 b;
        for (const Vec3& p : positions) b.expand(p);
        return b;
    }

    Bounds3 triangleBounds(size_t i) const {
        const auto& t = triangles[i];
        Bounds3 b(positions[t[0]], positions[t[1]]);
        b.expand(positions[t[2]]);
        return b;
    }
};

}  // namespace raylab
