#include "geometry/shape.h"

namespace raylab {

std::optional<Shape::PrimitiveHit> Shape::intersectAny(const Ray& ray, double tMin, double tMax,
                                                       const IntersectOptions& opt) const {
    std::optional<PrimitiveHit> best;
    // Each hit shrinks the interval, so later primitives only count if closer.
    for (uint32_t prim = 0, n = primitiveCount(); prim < n; ++prim) {
        if (const auto h = intersect(prim, ray, tMin, tMax, opt)) {
            tMax = h->t;
            best = PrimitiveHit{prim, *h};
        }
    }
    return best;
}

bool Shape::occludedAny(const Ray& ray, double tMin, double tMax,
                        const IntersectOptions& opt) const {
    for (uint32_t prim = 0, n = primitiveCount(); prim < n; ++prim)
        if (occluded(prim, ray, tMin, tMax, opt)) return true;
    return false;
}

}  // namespace raylab
