#pragma once
// Axis-aligned bounding boxes.

#include <cfloat>
#include <cmath>
#include <limits>

#include "geometry/vec.h"

namespace raylab {

struct Bounds3 {
    Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity()};
    Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
            -std::numeric_limits<double>::infinity()};

    Bounds3() = default;
    Bounds3(const Vec3& a, const Vec3& b) : lo(min(a, b)), hi(max(a, b)) {}

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    bool finite() const { return isFinite(lo) && isFinite(hi); }
    Vec3 centre() const { return (lo + hi) * 0.5; }
    Vec3 extent() const { return hi - lo; }

    void expand(const Vec3& p) { lo = min(lo, p); hi = max(hi, p); }
    void expand(const Bounds3& b) { lo = min(lo, b.lo); hi = max(hi, b.hi); }

    bool contains(const Vec3& p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
               p.z <= hi.z;
    }

    /// The box grown by a relative margin of a few float ulps of its largest
    /// coordinate. Embree's user-geometry traversal never runs in robust mode
    /// and stores boxes in float, so exact boxes can lose grazing hits.
    Bounds3 padded(double relative = 4.0 * FLT_EPSILON) const { return grown(padding(relative)); }
    /// The margin padded() adds.
    double padding(double relative = 4.0 * FLT_EPSILON) const {
        const double m = std::max(maxComponent(abs(lo)), maxComponent(abs(hi)));
        return relative * std::max(m, 1e-30) + 1e-30;
    }
    /// The box grown by `margin` on every side.
    Bounds3 grown(double margin) const {
        Bounds3 b = *this;
        b.lo -= Vec3{margin, margin, margin};
        b.hi += Vec3{margin, margin, margin};
        return b;
    }
    /// Surface area: proportional to the chance that a random ray meets the
    /// box (the surface area heuristic's measure).
    double surfaceArea() const {
        const Vec3 e = extent();
        return 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
};

}  // namespace raylab
