#pragma once
// Queries on a single-primitive shape (primitive 0) with explicit options,
// so the geometry tests read like the formulas they check.

#include <optional>

#include "geometry/shape.h"

namespace raylab {

inline IntersectOptions withPrecision(Precision p) {
    IntersectOptions o;
    o.precision = p;
    return o;
}

inline std::optional<ShapeHit> intersect1(const Shape& s, const Ray& ray, double tMin, double tMax,
                                          const IntersectOptions& opt = {}) {
    return s.intersect(0, ray, tMin, tMax, opt);
}

inline bool occluded1(const Shape& s, const Ray& ray, double tMin, double tMax,
                      const IntersectOptions& opt = {}) {
    return s.occluded(0, ray, tMin, tMax, opt);
}

inline SurfaceGeometry surface1(const Shape& s, const Ray& ray, const ShapeHit& hit,
                                const IntersectOptions& opt = {}) {
    return s.surfaceAt(0, ray, hit, opt, SurfaceDetail::Complete);
}

}  // namespace raylab
