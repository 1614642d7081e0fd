#pragma once
// What an accelerator reports for a closest-hit query.

#include <cstdint>

namespace raylab {

/// Which primitive of which object was hit, and where along the ray.
struct Hit {
    double t = 0;
    uint32_t object = 0;  ///< index into Scene::objects
    uint32_t prim = 0;    ///< primitive of the object's shape (a mesh's triangle, 0 otherwise)
    double u = 0, v = 0;  ///< the shape's primitive-local parameters (ShapeHit::u, v)
};

}  // namespace raylab
