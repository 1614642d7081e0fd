#pragma once
// What every analytic primitive (one primitive per shape) has in common, in
// one place: the primitive index is always 0, the float/double dispatch of
// the accuracy study, and the secondary-ray span of float arithmetic.
//
// A primitive class derives from AnalyticShape<Itself> and provides
//   Bounds3 bounds() const;
//   template <class T> std::optional<ShapeHit>
//       intersectT(const Ray&, double tMin, double tMax, const IntersectOptions&) const;
//   SurfaceGeometry surface(const Ray&, const ShapeHit&, SurfaceDetail) const;

#include "geometry/shape.h"

namespace raylab {

template <class Derived>
class AnalyticShape : public Shape {
public:
    uint32_t primitiveCount() const final { return 1; }
    Bounds3 bounds(uint32_t) const final { return self().bounds(); }
    Bounds3 bounds() const override = 0;

    std::optional<ShapeHit> intersect(uint32_t, const Ray& ray, double tMin, double tMax,
                                      const IntersectOptions& opt) const final {
        return opt.precision == Precision::Float
                   ? self().template intersectT<float>(ray, tMin, tMax, opt)
                   : self().template intersectT<double>(ray, tMin, tMax, opt);
    }

    /// Shape::occluded's answer, without its second virtual call: intersect
    /// is final here, so this call is direct and inlined, and the hit's u, v
    /// are left out where the compiler sees them unused (a feeler needs neither).
    bool occluded(uint32_t prim, const Ray& ray, double tMin, double tMax,
                  const IntersectOptions& opt) const final {
        return intersect(prim, ray, tMin, tMax, opt).has_value();
    }

    std::optional<PrimitiveHit> intersectAny(const Ray& ray, double tMin, double tMax,
                                             const IntersectOptions& opt) const final {
        if (const auto h = intersect(0, ray, tMin, tMax, opt)) return PrimitiveHit{0, *h};
        return std::nullopt;
    }

    bool occludedAny(const Ray& ray, double tMin, double tMax,
                     const IntersectOptions& opt) const final {
        return occluded(0, ray, tMin, tMax, opt);
    }

    SurfaceGeometry surfaceAt(uint32_t, const Ray& ray, const ShapeHit& hit,
                              const IntersectOptions& opt, SurfaceDetail detail) const final {
        SurfaceGeometry g = self().surface(ray, hit, detail);
        g.t = hit.t;
        // Float arithmetic solves relative to a point of the shape's own
        // (centre, base, plane point), which lies within its bounds.
        if (opt.precision == Precision::Float) g.span = maxComponent(abs(g.p - bounds().centre()));
        return g;
    }

private:
    const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace raylab
