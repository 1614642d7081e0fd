// Ear-clipping triangulation of a simple polygon (declared in primitives.h).
// The polygon is projected onto the plane of its two non-dominant normal axes
// (first onto its Newell plane when its corners are not planar), oriented
// counter-clockwise there, and ears are clipped until a triangle remains: an
// ear is a convex vertex whose triangle with its two neighbours contains no
// other remaining vertex (boundary included). O(n²) per clip in the worst
// case, fine for the 144-vertex gear faces of SPD. Collinear vertices are
// removed without emitting a zero-area triangle. If no ear exists (a
// self-intersecting input, or rounding), the convex vertex with the largest
// triangle is clipped anyway so the loop always terminates.
//
// triangulateFace adds the rule for mesh faces: a convex quad is split along
// its shorter diagonal.

#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/bounds.h"
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

/// The ring's corners moved onto the plane through their centroid with
/// normal n, or nothing when they lie on it already (within 1e-9 of the
/// polygon's size: rounding, not warp).
std::vector<Vec3> projectOntoNewellPlane(const std::vector<Vec3>& vertices,
                                         const std::vector<uint32_t>& ring, const Vec3& n) {
    const Vec3 unit = normalize(n);
    Vec3 centroid{};
    Bounds3 box;
    for (uint32_t i : ring) {
        centroid += vertices[i];
        box.expand(vertices[i]);
    }
    centroid = centroid / double(ring.size());
    const double tolerance = 1e-9 * maxComponent(box.extent());
    bool planar = true;
    for (uint32_t i : ring) planar = planar && std::abs(dot(unit, vertices[i] - centroid)) <= tolerance;
    if (planar) return {};
    std::vector<Vec3> out(vertices.size());
    for (uint32_t i : ring) out[i] = vertices[i] - unit * dot(unit, vertices[i] - centroid);
    return out;
}

/// Whether the quad (a, b, c, d) turns the same way at every corner about n:
/// convex, so both diagonals lie inside it.
bool convexQuad(const std::vector<Vec3>& q, const Vec3& n) {
    for (int i = 0; i < 4; ++i) {
        const Vec3& a = q[size_t(i)];
        const Vec3& b = q[size_t((i + 1) % 4)];
        const Vec3& c = q[size_t((i + 2) % 4)];
        if (!(dot(n, cross(b - a, c - b)) > 0)) return false;
    }
    return true;
}

}  // namespace

void triangulateFace(const std::vector<Vec3>& corners, std::vector<std::array<uint32_t, 3>>& out) {
    out.clear();
    if (corners.size() == 3) {
        out.push_back({0, 1, 2});
        return;
    }
    if (corners.size() == 4 && convexQuad(corners, newellNormal(corners))) {
        // Both splits are valid; the shorter diagonal keeps the triangles
        // closest to equilateral (tinyobjloader's rule and index order). The
        // lengths are compared in float as it did: at near ties (a torus's
        // quads) the split, and so the pictures of meshes rendered before, stay.
        const Vec3f e02 = Vec3f(corners[2]) - Vec3f(corners[0]);
        const Vec3f e13 = Vec3f(corners[3]) - Vec3f(corners[1]);
        const float d02 = lengthSquared(e02), d13 = lengthSquared(e13);
        if (d02 < d13) {
            out.push_back({0, 1, 2});
            out.push_back({0, 2, 3});
        } else {
            out.push_back({0, 1, 3});
            out.push_back({1, 2, 3});
        }
        return;
    }
    out = triangulatePolygon(corners);
}

std::vector<std::array<uint32_t, 3>> triangulateFace(const std::vector<Vec3>& corners) {
    std::vector<std::array<uint32_t, 3>> out;
    triangulateFace(corners, out);
    return out;
}

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
    // points down that axis so the polygon runs counter-clockwise in 2D. Corners
    // off the Newell plane (a warped OBJ face) are first moved onto it along
    // the normal, so the projection is the face as seen from its normal; planar
    // corners are used as they are, so collinear ones stay exactly collinear.
    const int drop = dominantAxis(n);
    const int ax = (drop + 1) % 3, ay = (drop + 2) % 3;
    const double flip = n[drop] < 0 ? -1.0 : 1.0;
    const std::vector<Vec3> onPlane = projectOntoNewellPlane(vertices, ring, n);
    const std::vector<Vec3>& source = onPlane.empty() ? vertices : onPlane;
    std::vector<Point2> pts(vertices.size());
    for (uint32_t i : ring) pts[i] = {source[i][ax], flip * source[i][ay]};

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
