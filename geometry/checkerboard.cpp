#include "geometry/checkerboard.h"

namespace raylab {

TriangleMesh makeCheckerboard(const Vec3& origin, const Vec3& edgeU, const Vec3& edgeV, int nu,
                              int nv) {
    TriangleMesh mesh;
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i)
            mesh.positions.push_back(origin + edgeU * (double(i) / nu) + edgeV * (double(j) / nv));
    const auto at = [&](int i, int j) { return uint32_t(j * (nu + 1) + i); };
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return mesh;
}

}  // namespace raylab
