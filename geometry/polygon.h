#pragma once
// Planar polygons with any number of vertices, convex or concave (also
// self-intersecting, under the even-odd or nonzero fill rule).
//
// makePolygon() validates the input (see its rules below), computes the
// Newell normal (robust to collinear leading vertices) and stores the
// vertices. intersect() first meets the polygon's plane (through the
// centroid, Newell normal), then decides inside/outside with one of two tests:
//
// - PolygonTest::Projected, the lecture's test: the plane hit point and the
//   vertices are projected by dropping the dominant axis of the normal, then
//   Sunday's crossing/winding count with the half-open rule (an upward edge
//   includes its start and excludes its end). Not watertight: neighbours
//   compute their hit points and edge tests from different planes and edge
//   directions, so rays through shared edges or vertices can miss both.
// - PolygonTest::Watertight, in ray space (Woop, Benthin & Wald 2013): the
//   vertices are translated to the ray origin, permuted so that the dominant
//   |d| axis is z and sheared so that the ray runs along +z; the crossing/
//   winding count is then taken around the 2D origin. A vertex's sheared
//   coordinates depend only on the vertex and the ray, every edge is evaluated
//   lower-endpoint first, the sign of each edge function is exact (recomputed
//   with error-free products when the rounded value is too small to trust)
//   and exact zeros are broken by a symbolic perturbation of the origin to
//   (+εx, +εy), εx << εy, the same for every polygon. The result equals the
//   test for a point in general position, so polygons that share edges and
//   vertices bit-exactly and tile a region are hit by exactly one of them,
//   never zero or two (measured in tests/geometry/test_polygon.cpp). From 16
//   vertices on, which side of the x axis each vertex lies on is computed 64
//   at a time as a bit mask (SIMD, the same roundings) and only the edges
//   where it changes are evaluated: the same answer with a fraction of the work
//   (tests/geometry/test_polygon_watertight.cpp). Boxes of 8 consecutive
//   vertices settle whole bytes of the mask without touching their vertices:
//   rounded arithmetic is monotone, so the sheared y computed at a box's
//   corners bounds that of every vertex in it exactly.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/frame.h"
#include "geometry/polygon_grid.h"
#include "geometry/primitives.h"
#include "geometry/analytic_shape.h"

namespace raylab {

/// Newell's normal of a closed polygon: twice the vector area, pointing to
/// the side from which the vertices run counter-clockwise. Computed relative
/// to the vertex mean, so it is accurate for polygons far from the origin.
Vec3 newellNormal(const std::vector<Vec3>& vertices);

class Polygon final : public AnalyticShape<Polygon> {
public:
    /// Validation rules (each violation throws std::invalid_argument naming it):
    /// - at least 3 vertices, all finite; consecutive duplicates (including
    ///   last == first) are dropped, and at least 3 distinct vertices must remain;
    /// - the vertices must not be collinear: the Newell area must exceed 1e-12
    ///   of the squared bounding-box diagonal;
    /// - the vertices must be coplanar: every vertex within
    ///   1e-5 · (bounding-box diagonal + largest |coordinate|) of the plane
    ///   through the vertex mean with the Newell normal; the message names the
    ///   worst vertex and its distance. (The second term absorbs 6-digit decimal
    ///   rounding of polygons far from the origin, as written by SPD.)
    /// - normals: empty, or one finite non-zero vector per input vertex.
    static std::unique_ptr<Polygon> create(const PolygonParams& params);

    /// Box of the vertices (grown by their planarity deviation), padded.
    Bounds3 bounds() const override;
    /// Plane hit (sidedness by the Newell normal, tMin < t < tMax), then the
    /// inside test chosen in PolygonParams (or IntersectOptions::polygonTest
    /// when set). ShapeHit u, v = in-plane coordinates of the hit relative to
    /// the vertex mean, along the frame tangents.
    template <class T>
    std::optional<ShapeHit> intersectT(const Ray& ray, double tMin, double tMax,
                                       const IntersectOptions& opt) const;
    /// Hit point (projected onto the plane), outward normal; the shading normal
    /// interpolates per-vertex normals with mean-value coordinates when given
    /// (flipped into the geometric normal's hemisphere if it points away).
    /// uv: the hit's coordinates in the polygon's bounding rectangle, u along
    /// the first edge (vertex 0 -> 1) and v along n × u, each scaled to [0, 1]
    /// (a quadrilateral listed counter-clockwise from its lower-left corner
    /// shows an image upright). dndu/dndv of interpolated normals are central
    /// differences (mean-value coordinates have no compact derivative).
    SurfaceGeometry surface(const Ray& ray, const ShapeHit& hit, SurfaceDetail detail) const;
    const char* kind() const override { return "polygon"; }
    /// Planar: the hit lies on the centroid plane, which is where a ray
    /// leaving it starts from (offset off it) and which it never crosses again.
    Revisit revisit() const override { return Revisit::None; }

    const std::vector<Vec3>& vertices() const { return m_vertices; }
    /// Per-vertex shading normals (NFF "pp"), or empty.
    const std::vector<Vec3>& normals() const { return m_normals; }
    const Vec3& normal() const { return m_frame.n; }
    FillRule fillRule() const { return m_rule; }
    /// The inside test this polygon was created with.
    PolygonTest insideTest() const { return m_test; }
    /// The exact filter in front of the watertight test, or null (small polygons).
    const PolygonGrid* grid() const { return m_grid.get(); }
    bool hasShadingNormals() const override { return !m_normals.empty(); }

    /// Use create(); public for std::make_unique.
    Polygon(std::vector<Vec3> vertices, std::vector<Vec3> normals, const Vec3& normal,
            const Vec3& centroid, double deviation, FillRule rule, PolygonTest test);

private:
    template <class T>
    bool insideProjected(const Vec3T<T>& p) const;
    /// \param chunkBoxes whether boxes of 8 vertices may settle the mask's
    ///   bytes (IntersectOptions::polygonChunkBoxes; the same answer either way)
    template <class T>
    bool insideWatertight(const Vec3T<T>& o, const Vec3T<T>& d, bool chunkBoxes) const;
    /// Whether the grid's error bound can hold for this polygon: every edge
    /// of nonzero length at least kGridMinEdge, |centroid| + radius at most
    /// kGridMaxScale (polygon.cpp).
    bool gridScale() const;
    /// The grid's answer for the plane hit o + t·d (cosine = n·d), or -1 when
    /// it cannot be trusted to equal the watertight test's (see polygon.cpp).
    int insideByGrid(const Ray& ray, double t, double cosine, const Vec3& local) const;
    bool accepts(int winding, int crossings) const;
    Vec3 interpolatedNormal(const Vec3& p) const;
    /// The unit shading normal at plane point p (ng without vertex normals).
    Vec3 shadingNormal(const Vec3& p) const;

    /// Coordinate axis `axis` of every vertex, in the precision T (structure of
    /// arrays: the inside tests pick axes at run time without branching per vertex).
    template <class T>
    const T* coords(int axis) const;
    /// Bit i of the result: whether vertex base + i (i < m) lies above the
    /// sheared x axis, as insideWatertight computes it; with `boxes`, whole
    /// chunks of vertices are decided from their boxes where the box does.
    template <class T>
    uint64_t aboveBits(size_t base, size_t m, bool boxes, int ky, int kz, T oy, T oz, T sy) const;
    /// Whether chunk boxes exist and may bound the sheared y of a ray with
    /// origin components oy, oz and shear sy (no overflow, no NaN).
    template <class T>
    bool chunkBoxesUsable(T oy, T oz, T sy) const;

    /// Per chunk of 8 consecutive vertices: the lowest and highest coordinate
    /// on each axis, in double and rounded to float (rounding is monotone:
    /// the float vertices' bounds); a precision's arrays are empty where its
    /// coordinates are too large for the boxes.
    struct ChunkBoxes {
        std::array<std::vector<double>, 3> lo, hi;
        std::array<std::vector<float>, 3> loF, hiF;
    };

    // Members in the order a ray query reads them: the plane, the grid and
    // the coordinate runs first, so a polygon test touches the object's
    // first three cache lines, not seven (SPD gears: 9,345 polygons of
    // ~400 bytes, most tests a cache miss away).
    Frame m_frame;      ///< n = unit Newell normal
    Vec3 m_centroid;    ///< vertex mean: the plane's reference point
    /// Exact filter in front of the watertight test (polygons with many
    /// vertices only; null otherwise).
    std::unique_ptr<const PolygonGrid> m_grid;
    double m_radius;     ///< largest vertex distance from the centroid
    double m_deviation;  ///< largest vertex distance from the plane
    /// x of every vertex, then y, then z (one allocation: SPD gears has
    /// 9,217 quads, and three vectors per precision were a third of a quad's
    /// memory, docs/benchmarks.md "Fresh memory").
    std::vector<double> m_coords;
    size_t m_count;  ///< vertices (m_vertices.size(), kept here with the hot members)
    /// Polygons with many vertices only (null otherwise).
    std::unique_ptr<const ChunkBoxes> m_chunks;
    FillRule m_rule;
    PolygonTest m_test;
    // Read by shading, the float path and construction.
    std::vector<float> m_coordsF;  ///< m_coords rounded to float
    std::vector<Vec3> m_vertices;
    std::vector<Vec3> m_normals;                  ///< unit per-vertex shading normals, or empty
    Bounds3 m_bounds;
    Frame m_uvFrame;  ///< t along the first edge, b = n × t: the (u, v) axes
    Vec2 m_uvOrigin;  ///< lower-left corner of the bounding rectangle in (t, b)
    Vec2 m_uvSize;    ///< its extent along t and b
    int m_dropAxis;  ///< dominant axis of the normal (Projected test)
};

}  // namespace raylab
