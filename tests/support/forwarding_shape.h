#pragma once
// A shape that answers every query as another, for tests that change one
// claim of a shape (its boxes, its Revisit) and keep the rest: a derived
// class overrides that one. Header-only, included as
// "support/forwarding_shape.h".

#include <memory>
#include <optional>
#include <utility>

#include "geometry/shape.h"

namespace raylab::test {

class ForwardingShape : public Shape {
public:
    explicit ForwardingShape(std::unique_ptr<Shape> inner) : m_inner(std::move(inner)) {}
    uint32_t primitiveCount() const override { return m_inner->primitiveCount(); }
    Bounds3 bounds(uint32_t prim) const override { return m_inner->bounds(prim); }
    Bounds3 bounds() const override { return m_inner->bounds(); }
    std::optional<ShapeHit> intersect(uint32_t prim, const Ray& ray, double tMin, double tMax,
                                      const IntersectOptions& opt) const override {
        return m_inner->intersect(prim, ray, tMin, tMax, opt);
    }
    SurfaceGeometry surfaceAt(uint32_t prim, const Ray& ray, const ShapeHit& hit,
                              const IntersectOptions& opt, SurfaceDetail detail) const override {
        return m_inner->surfaceAt(prim, ray, hit, opt, detail);
    }
    const char* kind() const override { return m_inner->kind(); }

protected:
    Shape& inner() { return *m_inner; }

private:
    std::unique_ptr<Shape> m_inner;
};

}  // namespace raylab::test
