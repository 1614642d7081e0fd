#include "geometry/quadric.h"

#include <cmath>

#include "geometry/quadratic.h"
#include "geometry/surface_parameters.h"
#include "geometry/validate.h"

namespace raylab {

namespace {

/// M·v for the symmetric matrix stored as xx, yy, zz, xy, xz, yz.
template <class T>
Vec3T<T> mulSym(const std::array<T, 6>& m, const Vec3T<T>& v) {
    return {m[0] * v.x + m[3] * v.y + m[4] * v.z, m[3] * v.x + m[1] * v.y + m[5] * v.z,
            m[4] * v.x + m[5] * v.y + m[2] * v.z};
}

double det3(const std::array<double, 6>& m) {
    return m[0] * (m[1] * m[2] - m[5] * m[5]) - m[3] * (m[3] * m[2] - m[5] * m[4]) +
           m[4] * (m[3] * m[5] - m[1] * m[4]);
}

/// Inverse of the symmetric matrix (same storage), given its determinant.
std::array<double, 6> inverseSym(const std::array<double, 6>& m, double det) {
    return {(m[1] * m[2] - m[5] * m[5]) / det, (m[0] * m[2] - m[4] * m[4]) / det,
            (m[0] * m[1] - m[3] * m[3]) / det, (m[4] * m[5] - m[3] * m[2]) / det,
            (m[3] * m[5] - m[4] * m[1]) / det, (m[3] * m[4] - m[0] * m[5]) / det};
}

}  // namespace

Quadric::Quadric(const std::array<double, 6>& m, const Vec3& g, double j, const Vec3& centre,
                 const Bounds3& clip, bool hasClip, const Bounds3& bounds)
    : m_m(m),
      m_g(g),
      m_j(j),
      m_centre(centre),
      m_clip(clip),
      m_hasClip(hasClip),
      m_bounds(bounds) {}

std::unique_ptr<Quadric> Quadric::create(const QuadricParams& p) {
    const double coeffs[10] = {p.A, p.B, p.C, p.D, p.E, p.F, p.G, p.H, p.I, p.J};
    const char* names[10] = {"A", "B", "C", "D", "E", "F", "G", "H", "I", "J"};
    bool anyNonZero = false;
    for (int i = 0; i < 10; ++i) {
        requireFinite("quadric", names[i], coeffs[i]);
        if (i < 9 && coeffs[i] != 0) anyNonZero = true;
    }
    if (!anyNonZero) throwInvalid("quadric", "coefficients A..I are all 0 (no surface)");
    if (p.hasClip) {
        requireFinite("quadric", "clip box lower corner", p.clip.lo);
        requireFinite("quadric", "clip box upper corner", p.clip.hi);
        if (p.clip.empty()) {
            throwInvalid("quadric", "clip box is empty (lower " + formatValue(p.clip.lo) +
                                        ", upper " + formatValue(p.clip.hi) + ")");
        }
    }

    // World-coordinate matrix form: Q = xᵀ M x + gᵀ x + J.
    const std::array<double, 6> m{p.A, p.B, p.C, p.D / 2, p.E / 2, p.F / 2};
    const Vec3 g{p.G, p.H, p.I};

    // Bounded (an ellipsoid) when M is definite (Sylvester: leading minors of M or -M > 0).
    const double m1 = m[0], m2 = m[0] * m[1] - m[3] * m[3], m3 = det3(m);
    const bool definite = (m1 > 0 && m2 > 0 && m3 > 0) || (m1 < 0 && m2 > 0 && m3 < 0);
    Bounds3 derived;
    bool hasDerived = false;
    Vec3 centre = p.hasClip ? p.clip.centre() : Vec3{};
    if (definite) {
        // Centre x_c = -M⁻¹ g / 2; Q(x) = (x - x_c)ᵀ M (x - x_c) + Q(x_c). The surface
        // (x - x_c)ᵀ M (x - x_c) = -Q(x_c) is real only when -Q(x_c) has M's sign.
        const std::array<double, 6> inv = inverseSym(m, m3);
        const Vec3 xc = mulSym(inv, g) * -0.5;
        const double qc = dot(xc, mulSym(m, xc)) + dot(g, xc) + p.J;
        const double kappa = -qc;
        if (!(kappa * m1 > 0)) {
            throwInvalid("quadric", std::string("ellipsoid has no real points (") +
                                        (kappa == 0 ? "a single point" : "empty") + ")");
        }
        // Extent along axis i: sqrt(κ (M⁻¹)_ii), from maximising x_i on the ellipsoid.
        const Vec3 e{std::sqrt(kappa * inv[0]), std::sqrt(kappa * inv[1]),
                     std::sqrt(kappa * inv[2])};
        derived = Bounds3(xc - e, xc + e);
        hasDerived = isFinite(e);
        centre = xc;
    }
    if (!p.hasClip && !hasDerived) {
        throwInvalid("quadric", "unbounded surface needs a clip box");
    }
    Bounds3 box = p.hasClip ? p.clip : derived;
    if (p.hasClip && hasDerived) {
        box.lo = max(p.clip.lo, derived.lo);
        box.hi = min(p.clip.hi, derived.hi);
    }
    if (box.empty()) box = Bounds3(centre, centre);  // surface misses the clip box
    const Bounds3 bounds = box.padded();
    if (!bounds.finite()) throwInvalid("quadric", "bounds are not finite");

    // Centred coordinates x = centre + q: Q = qᵀ M q + (2 M centre + g)ᵀ q + Q(centre).
    const Vec3 gc = mulSym(m, centre) * 2.0 + g;
    const double jc = dot(centre, mulSym(m, centre)) + dot(g, centre) + p.J;
    return std::make_unique<Quadric>(m, gc, jc, centre, p.clip, p.hasClip, bounds);
}

Bounds3 Quadric::bounds() const { return m_bounds; }

double Quadric::evaluate(const Vec3& p) const {
    const Vec3 q = p - m_centre;
    return dot(q, mulSym(m_m, q) + m_g) + m_j;
}

template <class T>
std::optional<ShapeHit> Quadric::intersectT(const Ray& ray, double tMin, double tMax,
                                            const IntersectOptions&) const {
    using V = Vec3T<T>;
    const std::array<T, 6> m{T(m_m[0]), T(m_m[1]), T(m_m[2]), T(m_m[3]), T(m_m[4]), T(m_m[5])};
    const V g(m_g);
    const V q(ray.o - m_centre);  // subtracted in double before rounding to T
    const V d(ray.d);
    const V mq = mulSym(m, q);
    const T a = dot(d, mulSym(m, d));
    const T h = dot(d, mq + g * T(0.5));
    const T c = dot(q, mq + g) + static_cast<T>(m_j);
    const T disc = h * h - a * c;
    const QuadraticRoots<T> roots = solveQuadraticHalfB(a, h, c, disc);
    if (roots.count == 0) return std::nullopt;

    // dQ/dt / 2 = a t + h = ∓sqrt(disc) at the roots: entering (front) is the smaller
    // root when a > 0, the larger when a < 0; a linear root enters when h < 0.
    const bool proper = disc > T(0);
    const bool front[2] = {roots.count == 1 ? h < T(0) : (proper && a > T(0)), proper && a < T(0)};
    const T ts[2] = {roots.t0, roots.t1};
    const V lo(m_clip.lo - m_centre), hi(m_clip.hi - m_centre);
    for (int i = 0; i < roots.count; ++i) {
        const double t = static_cast<double>(ts[i]);
        if (!(tMin < t && t < tMax) || !acceptsFacing(m_sides, front[i])) continue;
        if (m_hasClip) {
            const V p = q + d * ts[i];
            if (!(p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
                  p.z <= hi.z)) {
                continue;  // outside the clip box: try the far root
            }
        }
        return ShapeHit{t, 0.0, 0.0};
    }
    return std::nullopt;
}

template std::optional<ShapeHit> Quadric::intersectT<float>(const Ray&, double, double,
                                                           const IntersectOptions&) const;
template std::optional<ShapeHit> Quadric::intersectT<double>(const Ray&, double, double,
                                                            const IntersectOptions&) const;

SurfaceGeometry Quadric::surface(const Ray& ray, const ShapeHit& hit, SurfaceDetail detail) const {
    SurfaceGeometry g;
    g.p = ray.at(hit.t);
    const Vec3 q = g.p - m_centre;
    const Vec3 gradient = mulSym(m_m, q) * 2.0 + m_g;
    Vec3 n = normalize(gradient);
    if (n == Vec3{} || !isFinite(n)) n = -normalize(ray.d);  // singular point
    g.ng = g.ns = n;
    g.frontFace = dot(ray.d, n) < 0;
    if (detail != SurfaceDetail::Normals) surfaceParameters(g, q, gradient);
    return g;
}

void Quadric::surfaceParameters(SurfaceGeometry& g, const Vec3& q, const Vec3& gradient) const {
    // The parametrisation's frame: pole +y, as a sphere's default.
    static const Frame frame = Frame::fromNormal({0, 1, 0});
    const double s = length(q);
    const Vec3 w = s > 0 ? q / s : Vec3{0, 0, 1};
    const LocalParameters l = sphericalParameters(frame.toLocal(w));
    g.uv = l.uv;
    // p(u, v) = centre + s(u, v) w(u, v) with Q(p) = 0, so ∇Q·∂p/∂u = 0 gives
    // ∂p/∂u = s (w_u - w (∇Q·w_u) / (∇Q·w)); likewise for v.
    const Vec3 wu = frame.toWorld(l.dpdu), wv = frame.toWorld(l.dpdv);
    const double along = dot(gradient, w);
    const Vec3 dpdu = (wu - w * (dot(gradient, wu) / along)) * s;
    const Vec3 dpdv = (wv - w * (dot(gradient, wv) / along)) * s;
    const double gradientLength = length(gradient);
    if (!(s > 0) || !isFinite(dpdu) || !isFinite(dpdv) || !(gradientLength > 0) ||
        lengthSquared(cross(dpdu, dpdv)) == 0) {
        // Centre on the surface, or its direction grazes it: any tangent frame.
        const Frame tangents = Frame::fromNormal(g.ng);
        g.dpdu = tangents.t;
        g.dpdv = tangents.b;
        return;
    }
    g.dpdu = dpdu;
    g.dpdv = dpdv;
    // n = ∇Q / |∇Q| with ∇Q = 2 M q + g: dn = (I - n nᵀ) 2 M dp / |∇Q|.
    const auto dn = [&](const Vec3& dp) {
        const Vec3 dGradient = mulSym(m_m, dp) * 2.0;
        return (dGradient - g.ns * dot(g.ns, dGradient)) / gradientLength;
    };
    g.dndu = dn(dpdu);
    g.dndv = dn(dpdv);
}

std::unique_ptr<Shape> makeQuadric(const QuadricParams& params) { return Quadric::create(params); }

}  // namespace raylab
