#include "shading/normal_mapping.h"

#include <cmath>

#include "geometry/frame.h"

namespace raylab {

Vec3 bumpedNormal(const SurfaceGeometry& sg, const Texture& height, double scale,
                  const TextureCoords& tc, TextureFilter filter) {
    // A height difference across half a texel of point sampling is 0 or a
    // jump: bump maps read at least bilinearly.
    if (filter == TextureFilter::Point) filter = TextureFilter::Bilinear;
    double du = 0.5 * (std::abs(tc.duvdx.x) + std::abs(tc.duvdy.x));
    double dv = 0.5 * (std::abs(tc.duvdx.y) + std::abs(tc.duvdy.y));
    if (!(du > 0)) du = 0.0005;
    if (!(dv > 0)) dv = 0.0005;
    // The three lookups share the hit's footprint (and its level of detail).
    const LookupFootprint fp = height.footprint(tc, filter);
    const double h = scale * height.scalar(tc.uv, fp, filter);
    const double hu = scale * height.scalar(Vec2{tc.uv.x + du, tc.uv.y}, fp, filter);
    const double hv = scale * height.scalar(Vec2{tc.uv.x, tc.uv.y + dv}, fp, filter);
    // p' = p + h n: dp'/du = dp/du + dh/du n + h dn/du (and the same in v).
    const Vec3 dpdu = sg.dpdu + sg.ns * ((hu - h) / du) + sg.dndu * h;
    const Vec3 dpdv = sg.dpdv + sg.ns * ((hv - h) / dv) + sg.dndv * h;
    const Vec3 n = cross(dpdu, dpdv);
    if (!(lengthSquared(n) > 0) || !isFinite(n)) return sg.ns;
    const Vec3 unit = normalize(n);
    return dot(unit, sg.ns) < 0 ? -unit : unit;
}

Vec3 normalMappedNormal(const SurfaceGeometry& sg, const Texture& map, const TextureCoords& tc,
                        TextureFilter filter) {
    const Color c = map.color(tc, filter);
    const Vec3 local{2 * c.r - 1, 2 * c.g - 1, 2 * c.b - 1};
    const Vec3& n = sg.ns;
    Vec3 t = sg.dpdu - n * dot(n, sg.dpdu);
    Vec3 b;
    if (lengthSquared(t) > 0 && isFinite(t)) {
        t = normalize(t);
        b = cross(n, t);
        if (dot(b, sg.dpdv) < 0) b = -b;  // mirrored uv: B still points to +v
    } else {
        const Frame f = Frame::fromNormal(n);
        t = f.t;
        b = f.b;
    }
    const Vec3 bent = t * local.x + b * local.y + n * local.z;
    if (!(lengthSquared(bent) > 0) || !isFinite(bent)) return n;
    return normalize(bent);
}

}  // namespace raylab
