#pragma once
// Factories for every analytic primitive. They validate their parameters and
// throw std::invalid_argument with a message that names the problem
// ("cylinder: radius must be > 0 (got -1)"); loaders add file and line.
// Each primitive's class and math live in its own file (sphere.h, plane.h, ...).

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/bounds.h"
#include "geometry/shape.h"
#include "geometry/vec.h"

namespace raylab {

/// Sphere; `pole` orients its (u, v) parametrisation (docs/scene-format.md):
/// the scene's up axis +y by default, like the camera's default up.
std::unique_ptr<Shape> makeSphere(const Vec3& centre, double radius, const Vec3& pole = {0, 1, 0});

/// Infinite plane through `point` with outward `normal`, given finite bounds:
/// a square of half-size `halfExtent` around `point` (Embree drops infinite boxes).
std::unique_ptr<Shape> makePlane(const Vec3& point, const Vec3& normal, double halfExtent = 1e5);

std::unique_ptr<Shape> makeDisk(const Vec3& centre, const Vec3& normal, double radius);

/// Cylinder (equal radii), cone (one radius 0) or truncated cone between two end points.
struct ConeParams {
    Vec3 base;
    double baseRadius = 1;
    Vec3 apex;
    double apexRadius = 1;
    bool capped = false;  ///< disk caps at both ends (where the radius is > 0)
};
std::unique_ptr<Shape> makeCone(const ConeParams& params);

/// A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0, clipped to a box.
struct QuadricParams {
    double A = 0, B = 0, C = 0, D = 0, E = 0, F = 0, G = 0, H = 0, I = 0, J = 0;
    Bounds3 clip;           ///< clipping box (required finite unless it can be derived)
    bool hasClip = false;
};
std::unique_ptr<Shape> makeQuadric(const QuadricParams& params);

enum class FillRule { EvenOdd, NonZero };

struct PolygonParams {
    std::vector<Vec3> vertices;  ///< counter-clockwise seen from the front (outward) side
    std::vector<Vec3> normals;   ///< optional per-vertex shading normals (NFF "pp")
    FillRule rule = FillRule::EvenOdd;
    PolygonTest test = PolygonTest::Watertight;
};
std::unique_ptr<Shape> makePolygon(const PolygonParams& params);

/// Largest polygon triangulatePolygon accepts (ear clipping is quadratic).
constexpr size_t kMaxTriangulatedVertices = 16384;

/// Triangulates a simple polygon (convex or concave; a warped one on its
/// Newell plane) by ear clipping;
/// returns indices into `vertices`, wound like the polygon. Throws
/// std::invalid_argument beyond kMaxTriangulatedVertices vertices.
std::vector<std::array<uint32_t, 3>> triangulatePolygon(const std::vector<Vec3>& vertices);

/// Triangulates one mesh face (an OBJ `f`): a triangle as it is, a convex quad
/// along its shorter diagonal, anything else (concave quads, n-gons) by
/// triangulatePolygon. Indices are into `corners`, wound like the face.
/// Throws std::invalid_argument like triangulatePolygon (collinear or fewer
/// than 3 distinct corners, too many corners).
std::vector<std::array<uint32_t, 3>> triangulateFace(const std::vector<Vec3>& corners);

/// triangulateFace into `out` (cleared first): a mesh loader reusing one
/// vector allocates nothing for triangles and convex quads.
void triangulateFace(const std::vector<Vec3>& corners, std::vector<std::array<uint32_t, 3>>& out);

}  // namespace raylab
