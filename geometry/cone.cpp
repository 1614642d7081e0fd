#include "geometry/cone.h"

#include <cmath>

#include "geometry/quadratic.h"
#include "geometry/surface_parameters.h"
#include "geometry/validate.h"

namespace raylab {

namespace {
/// v of cap hits in ShapeHit (side hits have v = z / height in [0, 1]).
constexpr double kBaseCapV = -1.0;
constexpr double kApexCapV = 2.0;
}  // namespace

Cone::Cone(const ConeParams& p)
    : m_base(p.base),
      m_frame(Frame::fromNormal(normalize(p.apex - p.base))),
      m_height(length(p.apex - p.base)),
      m_r0(p.baseRadius),
      m_r1(p.apexRadius),
      m_slope(p.baseRadius == p.apexRadius ? 0.0 : (p.apexRadius - p.baseRadius) / m_height),
      m_capped(p.capped) {}

const char* Cone::kind() const { return m_r0 == m_r1 ? "cylinder" : "cone"; }

double Cone::radiusAt(double z) const {
    // Exactly the given radii at the ends (r0 + k·height need not round to r1).
    return z == 0.0 ? m_r0 : z == m_height ? m_r1 : m_r0 + m_slope * z;
}

Bounds3 Cone::sliceBox(double z0, double z1) const {
    const Vec3 c0 = m_base + m_frame.n * z0, c1 = m_base + m_frame.n * z1;
    const Vec3 e0 = diskHalfExtent(m_frame.n, radiusAt(z0));
    const Vec3 e1 = diskHalfExtent(m_frame.n, radiusAt(z1));
    Bounds3 b(c0 - e0, c0 + e0);
    b.expand(Bounds3(c1 - e1, c1 + e1));
    return b;
}

Bounds3 Cone::bounds() const { return sliceBox(0.0, m_height).padded(); }

void Cone::appendCoveringBoxes(uint32_t, const IntersectOptions& opt,
                               std::vector<Bounds3>& out) const {
    if (opt.precision != Precision::Double) {
        out.push_back(bounds());
        return;
    }
    // A slice of the solid is the convex hull of its two end disks, so the
    // slices' boxes contain it; adjacent slices share an end disk.
    const auto end = [&](int i, int n) { return i == n ? m_height : m_height * i / n; };
    // The choice needs only the slices' areas: per axis, the box of the two
    // end disks spans from the lower of centre - half-extent to the higher
    // of centre + half-extent, with half-extents r·sqrt(1 - n_i²).
    const Vec3 unitDisk = diskHalfExtent(m_frame.n, 1.0);
    const auto sliceArea = [&](double z0, double z1) {
        double extent[3];
        for (int a = 0; a < 3; ++a) {
            const double c0 = m_frame.n[a] * z0, c1 = m_frame.n[a] * z1;
            const double e0 = unitDisk[a] * radiusAt(z0), e1 = unitDisk[a] * radiusAt(z1);
            extent[a] = std::max(c0 + e0, c1 + e1) - std::min(c0 - e0, c1 - e1);
        }
        return 2 * (extent[0] * extent[1] + extent[1] * extent[2] + extent[2] * extent[0]);
    };
    int best = 1;
    double bestArea = kCoveringAreaGain * sliceArea(0.0, m_height);
    for (int n = 2; n <= kMaxCoveringBoxes; ++n) {
        double area = 0;
        for (int i = 0; i < n; ++i) area += sliceArea(end(i, n), end(i + 1, n));
        if (area <= bestArea) {
            best = n;
            bestArea = area;
        }
    }
    if (best == 1) {
        out.push_back(bounds());
        return;
    }
    // Each slice gets the whole box's margin, which covers the rounding of the test.
    const double margin = sliceBox(0.0, m_height).padding();
    for (int i = 0; i < best; ++i)
        out.push_back(sliceBox(end(i, best), end(i + 1, best)).grown(margin));
}

template <class T>
std::optional<ShapeHit> Cone::intersectT(const Ray& ray, double tMin, double tMax,
                                         const IntersectOptions&) const {
    using V = Vec3T<T>;
    // Local frame: base at the origin, z along the axis (orthonormal, so t is unchanged).
    const V ex(m_frame.t), ey(m_frame.b), ez(m_frame.n);
    const V w(ray.o - m_base);  // subtracted in double before rounding to T
    const V dw(ray.d);
    const T ox = dot(w, ex), oy = dot(w, ey), oz = dot(w, ez);
    const T dx = dot(dw, ex), dy = dot(dw, ey), dz = dot(dw, ez);
    const T height = static_cast<T>(m_height);
    const T r0 = static_cast<T>(m_r0);
    const T k = static_cast<T>(m_slope);

    double best = tMax;
    ShapeHit hit;
    bool found = false;
    const auto consider = [&](T tt, bool front, double u, double v) {
        const double t = static_cast<double>(tt);
        if (tMin < t && t < best && acceptsFacing(m_sides, front)) {
            best = t;
            hit = ShapeHit{t, u, v};
            found = true;
        }
    };

    // Side: (ox + t dx)² + (oy + t dy)² = (r0 + k (oz + t dz))², i.e. a t² + 2 h t + c = 0.
    const T ro = r0 + k * oz;  // radius at the origin's height (negative on the mirror side)
    const T a = dx * dx + dy * dy - (k * dz) * (k * dz);
    const T h = ox * dx + oy * dy - (k * dz) * ro;
    const T c = ox * ox + oy * oy - ro * ro;
    T disc;
    if (k == T(0) && a > T(0)) {
        // Cylinder: r² - |f|² with f the 2D closest point of the ray line to the axis,
        // accurate when the cylinder is thin and far away (as for the sphere).
        const T fx = ox - dx * (h / a), fy = oy - dy * (h / a);
        const T lf = std::sqrt(fx * fx + fy * fy);
        disc = a * ((r0 - lf) * (r0 + lf));
    } else {
        disc = h * h - a * c;
    }
    const QuadraticRoots<T> roots = solveQuadraticHalfB(a, h, c, disc);
    if (roots.count > 0) {
        // dF/dt / 2 = a t + h, which equals ∓sqrt(disc) at the two roots: the root that
        // enters the solid (front face) is the smaller one for a > 0, the larger for a < 0;
        // a single linear root (a == 0) enters when h < 0. A double root only grazes.
        const bool proper = disc > T(0);
        const bool front0 = roots.count == 1 ? h < T(0) : (proper && a > T(0));
        const bool front1 = proper && a < T(0);
        const T ts[2] = {roots.t0, roots.t1};
        const bool fronts[2] = {front0, front1};
        for (int i = 0; i < roots.count; ++i) {
            const T z = oz + ts[i] * dz;
            if (z >= T(0) && z <= height) {  // inclusive rim; excludes the mirror nappe
                consider(ts[i], fronts[i], 0.0, static_cast<double>(z / height));
            }
        }
    }

    // Caps: outward normals -axis (base) and +axis (apex).
    if (m_capped && dz != T(0)) {
        const auto cap = [&](T zc, T radius, bool front, double v) {
            if (!(radius > T(0))) return;
            const T t = (zc - oz) / dz;
            const T x = ox + t * dx, y = oy + t * dy;
            const T rho2 = x * x + y * y;
            if (rho2 <= radius * radius) {
                consider(t, front, static_cast<double>(std::sqrt(rho2) / radius), v);
            }
        };
        cap(T(0), r0, dz > T(0), kBaseCapV);
        cap(height, static_cast<T>(m_r1), dz < T(0), kApexCapV);
    }
    if (!found) return std::nullopt;
    return hit;
}

template std::optional<ShapeHit> Cone::intersectT<float>(const Ray&, double, double,
                                                        const IntersectOptions&) const;
template std::optional<ShapeHit> Cone::intersectT<double>(const Ray&, double, double,
                                                         const IntersectOptions&) const;

SurfaceGeometry Cone::surface(const Ray& ray, const ShapeHit& hit, SurfaceDetail detail) const {
    SurfaceGeometry g;
    g.p = ray.at(hit.t);
    Vec3 n;
    const bool baseCap = hit.v < 0, apexCap = hit.v > 1;
    if (baseCap) {
        n = -m_frame.n;
    } else if (apexCap) {
        n = m_frame.n;
    } else {
        const Vec3 local = m_frame.toLocal(g.p - m_base);
        const double rho = std::sqrt(local.x * local.x + local.y * local.y);
        if (rho > 0) {
            // Gradient of x² + y² - r(z)²: (x, y, -r k) with r = ρ on the surface.
            n = m_frame.toWorld(normalize(Vec3{local.x / rho, local.y / rho, -m_slope}));
        } else {
            // Apex of a cone: the side normals (cos φ, sin φ, -k) average to (0, 0, -k).
            n = m_slope < 0 ? m_frame.n : -m_frame.n;
        }
    }
    g.ng = g.ns = n;
    g.frontFace = dot(ray.d, n) < 0;
    if (detail != SurfaceDetail::Normals) {
        const Vec3 local = m_frame.toLocal(g.p - m_base);
        if (baseCap || apexCap) {
            const LocalParameters l = polarParameters(local.x, local.y, baseCap ? m_r0 : m_r1);
            g.uv = l.uv;
            g.dpdu = m_frame.toWorld(l.dpdu);
            g.dpdv = m_frame.toWorld(l.dpdv);
        } else {
            // p(u, v) = base + (r cos φ, r sin φ, z) with φ = 2πu, z = v·height,
            // r = r0 + k z; the normal (cos φ, sin φ, -k) / sqrt(1 + k²) turns
            // with φ only.
            const Azimuth a(local.x, local.y);
            g.uv = {a.u, local.z / m_height};
            g.dpdu = m_frame.toWorld(Vec3{-local.y, local.x, 0} * kTwoPi);
            g.dpdv = m_frame.toWorld(Vec3{m_slope * a.cosPhi, m_slope * a.sinPhi, 1} * m_height);
            const double inv = 1 / std::sqrt(1 + m_slope * m_slope);
            g.dndu = m_frame.toWorld(Vec3{-a.sinPhi, a.cosPhi, 0} * (kTwoPi * inv));
        }
    }
    return g;
}

std::unique_ptr<Shape> makeCone(const ConeParams& p) {
    const char* shape = p.baseRadius == p.apexRadius ? "cylinder" : "cone";
    requireFinite(shape, "base", p.base);
    requireFinite(shape, "apex", p.apex);
    requireFinite(shape, "baseRadius", p.baseRadius);
    requireFinite(shape, "apexRadius", p.apexRadius);
    if (p.baseRadius < 0) {
        throwInvalid(shape, "baseRadius must be >= 0 (got " + formatValue(p.baseRadius) + ")");
    }
    if (p.apexRadius < 0) {
        throwInvalid(shape, "apexRadius must be >= 0 (got " + formatValue(p.apexRadius) + ")");
    }
    if (p.baseRadius == 0 && p.apexRadius == 0) {
        throwInvalid(shape, "radius must be > 0 (both baseRadius and apexRadius are 0)");
    }
    const double height = length(p.apex - p.base);
    if (!(height > 0) || !std::isfinite(height)) {
        throwInvalid(shape, "base and apex must be distinct finite points (got " +
                                formatValue(p.base) + " and " + formatValue(p.apex) + ")");
    }
    return std::make_unique<Cone>(p);
}

}  // namespace raylab
