// Ear-clipping triangulation of a simple planar polygon (declared in
// primitives.h). The polygon is projected onto the plane of its two
// non-dominant normal axes, oriented counter-clockwise there, and ears are
// clipped until a triangle remains: an ear is a convex vertex whose triangle
// with its two neighbours contains no other remaining vertex (boundary
// included). O(n²) per clip in the worst case, fine for the 144-vertex gear
// faces of SPD. Collinear vertices are removed without emitting a zero-area
// triangle. If no ear exists (a self-intersecting input, or rounding), the
// convex vertex with the largest triangle is clipped anyway so the loop always
// terminates.

#include <stdexcept>
#include <string>

#include "geometry/polygon.h"
#include "geometry/primitives.h"
#include "geometry/validate.h"

namespace raylab {

namespace {

struct Point2 {
    double x, y;
};

/// Twice the signed area of (a, b, c): > 0 counter-clockwise.
double orient(const Point2& a, const Point2& b, const Point2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// p inside or on the boundary of the counter-clockwise triangle (a, b, c).
bool inTriangle(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
    return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0;
}

}  // namespace

std::vector<std::array<uint32_t, 3>> triangulatePolygon(const std::vector<Vec3>& vertices) {
    if (vertices.size() < 3) {
        throwInvalid("triangulate",
                     "needs at least 3 vertices (got " + std::to_string(vertices.size()) + ")");
    }
    // Ear clipping is quadratic: 20000 vertices take ~2 s, 300000 would take
    // many minutes. Beyond the cap the analytic polygon is the right tool.
    if (vertices.size() > kMaxTriangulatedVertices) {
        throwInvalid("triangulate", "a polygon of " + std::to_string(vertices.size()) +
                                        " vertices exceeds the ear-clipping limit of " +
                                        std::to_string(kMaxTriangulatedVertices) +
                                        " (render it as an analytic polygon)");
    }
    for (size_t i = 0; i < vertices.size(); ++i) {
        requireFinite("triangulate", "vertex", vertices[i]);
    }
    // Remaining vertices as indices, consecutive duplicates dropped.
    std::vector<uint32_t> ring;
    for (uint32_t i = 0; i < vertices.size(); ++i) {
        if (!ring.empty() && vertices[i] == vertices[ring.back()]) continue;
        ring.push_back(i);
    }
    while (ring.size() > 1 && vertices[ring.back()] == vertices[ring.front()]) ring.pop_back();
    if (ring.size() < 3) throwInvalid("triangulate", "fewer than 3 distinct vertices");

    std::vector<Vec3> distinct;
    for (uint32_t i : ring) distinct.push_back(vertices[i]);
    const Vec3 n = newellNormal(distinct);
    if (!(lengthSquared(n) > 0)) throwInvalid("triangulate", "vertices are collinear (zero area)");

    // Project by dropping the dominant normal axis; flip one axis when the normal
    // points down that axis so the polygon runs counter-clockwise in 2D.
    const int drop = dominantAxis(n);
    const int ax = (drop + 1) % 3, ay = (drop + 2) % 3;
    const double flip = n[drop] < 0 ? -1.0 : 1.0;
    std::vector<Point2> pts(vertices.size());
    for (uint32_t i : ring) pts[i] = {vertices[i][ax], flip * vertices[i][ay]};

    std::vector<std::array<uint32_t, 3>> triangles;
    triangles.reserve(ring.size() - 2);
    while (ring.size() > 3) {
        const size_t m = ring.size();
        size_t ear = m;       // first true ear found
        size_t fallback = m;  // convex vertex with the largest triangle
        double fallbackArea = -1;
        for (size_t k = 0; k < m && ear == m; ++k) {
            const uint32_t ip = ring[(k + m - 1) % m], ic = ring[k], in = ring[(k + 1) % m];
            const double area = orient(pts[ip], pts[ic], pts[in]);
            if (area == 0) {
                ear = k;  // collinear: remove it, no triangle
                break;
            }
            if (area < 0) continue;  // reflex
            if (area > fallbackArea) {
                fallbackArea = area;
                fallback = k;
            }
            bool empty = true;
            for (size_t j = 0; j < m && empty; ++j) {
                const uint32_t iv = ring[j];
                if (iv == ip || iv == ic || iv == in) continue;
                const Point2& p = pts[iv];
                // A vertex at the same position as a corner (a touching polygon) is no obstacle.
                const auto same = [&](uint32_t q) { return p.x == pts[q].x && p.y == pts[q].y; };
                if (same(ip) || same(ic) || same(in)) continue;
                empty = !inTriangle(p, pts[ip], pts[ic], pts[in]);
            }
            if (empty) ear = k;
        }
        if (ear == m) ear = fallback != m ? fallback : 0;
        const uint32_t ip = ring[(ear + m - 1) % m], ic = ring[ear], in = ring[(ear + 1) % m];
        if (orient(pts[ip], pts[ic], pts[in]) != 0) triangles.push_back({ip, ic, in});
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(ear));
    }
    if (orient(pts[ring[0]], pts[ring[1]], pts[ring[2]]) != 0) {
        triangles.push_back({ring[0], ring[1], ring[2]});
    }
    return triangles;
}

}  // namespace raylab
