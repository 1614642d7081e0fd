#pragma once
// The one interface every surface implements: analytic primitives (sphere,
// plane, disk, polygon, cylinder/cone, quadric) and triangle meshes alike.
// Pure math: no Embree, no materials. A shape is a set of primitives indexed
// 0..primitiveCount()-1 (one for an analytic shape, one per triangle for a
// mesh); the Embree user-geometry callbacks and the naive all-objects loop
// both call it, so the two accelerators see identical hits.
//
// Two-step intersection (pbrt's BasicIntersect / InteractionFromIntersection):
// intersect() returns only t and two primitive-local parameters; surfaceAt()
// computes point, normals and surface parameters once, for the hit that wins.

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/bounds.h"
#include "geometry/ray.h"
#include "geometry/vec2.h"

namespace raylab {

class TriangleMesh;

/// Which side of a surface can be hit. Normals always point "outward"
/// (the side a one-sided object shows); sidedness only filters hits.
enum class Sidedness {
    Outside,  ///< only hits from the outward side count (one-sided)
    Inside,   ///< only hits from the inside count (NFF's negative radius)
    Both,     ///< two-sided, required for transmitters
};

/// Arithmetic used by the analytic intersectors (accuracy study knob).
enum class Precision { Float, Double };

/// Inside test of planar polygons: the lecture's projected 2D crossing test, or
/// the watertight ray-space test (shear to +z, edge functions).
enum class PolygonTest { Projected, Watertight };

/// The accuracy knobs of one render that the intersectors read. Chosen when
/// the accelerator is built and handed to every query: never stored in the
/// scene, so one scene can be rendered with different settings side by side.
struct IntersectOptions {
    Precision precision = Precision::Double;
    /// When set, every polygon uses this inside test instead of its own.
    std::optional<PolygonTest> polygonTest;
    /// Large polygons answer most watertight inside tests from a grid that
    /// gives exactly the watertight test's answer (geometry/polygon_grid.h);
    /// off only to compare the two (tests, `raylab bench primitives`).
    bool polygonGrid = true;
    /// Polygons with many vertices settle whole bytes of the watertight test's
    /// bit mask from boxes of 8 vertices, exactly as vertex by vertex
    /// (geometry/polygon.h); off only to compare the two (tests).
    bool polygonChunkBoxes = true;
};

/// Minimal record of a candidate hit.
struct ShapeHit {
    double t = 0;  ///< ray parameter, in units of |d|
    double u = 0;  ///< primitive-local parameters (meaning per shape, internal)
    double v = 0;
};

/// How much of the surface record a caller needs. The parameters and their
/// derivatives cost trigonometry on spheres and cones, so the integrator asks
/// for them only when an effect (textures, footprints) reads them.
enum class SurfaceDetail {
    Normals,      ///< p, ng, ns, frontFace, span, color
    Derivatives,  ///< also dpdu, dpdv, dndu, dndv; uv may stay zero where it costs
                  ///< trigonometry (a sphere's), bit for bit the derivatives of Complete
    Complete,     ///< also uv
};

/// Full local geometry of the winning hit.
struct SurfaceGeometry {
    double t = 0;          ///< ray parameter of the hit (a triangle's recomputed in double)
    Vec3 p;                ///< hit point
    Vec3 ng;               ///< unit geometric normal, pointing outward
    Vec3 ns;               ///< unit shading normal, pointing outward
    bool frontFace = true; ///< true when the ray arrives from the outward side
    /// Extent around p of the primitive's float-rounded geometry, which sizes
    /// the secondary-ray offset (geometry/spawn.h): a triangle's largest
    /// vertex distance from p, a float-precision shape's distance from p to
    /// its bounds' centre, 0 for shapes intersected in double.
    double span = 0;
    /// Colour of the surface point that multiplies the material's kd: a
    /// mesh's interpolated vertex colours, white (1, 1, 1) for every other surface.
    Vec3 color{1, 1, 1};
    // SurfaceDetail::Complete (the derivatives also for Derivatives; zero otherwise). docs/scene-format.md
    // documents each primitive's parametrisation.
    Vec2 uv;               ///< surface parameters, [0,1]² unless documented otherwise
    Vec3 dpdu, dpdv;       ///< ∂p/∂u, ∂p/∂v (tangent to the surface)
    Vec3 dndu, dndv;       ///< ∂ns/∂u, ∂ns/∂v of the unit shading normal
};

/// True when a hit with the given facing is accepted under the sidedness rule.
inline bool acceptsFacing(Sidedness s, bool frontFace) {
    return s == Sidedness::Both || (s == Sidedness::Outside) == frontFace;
}

/// Which rays that leave a point of a shape could meet the shape again:
/// rays of a shape with one primitive, spawned by geometry/spawn.h's robust
/// rule and tested in double precision (the offset keeps such a ray's start
/// strictly on the side it leaves into; tests/geometry/test_revisit.cpp).
/// Where none can, an accelerator may leave the shape's test out of the
/// ray's queries (the integrator's Departure): the answers stay the same.
enum class Revisit {
    Any,     ///< any ray may (the default: curved non-convex surfaces, meshes)
    Inward,  ///< only a ray leaving against the geometric normal: the boundary
             ///< of a convex solid with outward normals. Leaving outwards, a ray
             ///< stays in the open half-space beyond the tangent plane at its
             ///< start, which the solid does not reach.
    None,    ///< none: a planar shape, whose plane a ray leaving it never crosses again
};

class Shape {
public:
    virtual ~Shape() = default;

    /// Number of primitives (1 for an analytic shape, triangles for a mesh).
    virtual uint32_t primitiveCount() const = 0;
    /// Tight, finite world-space box of primitive `prim` (never infinite:
    /// Embree drops such boxes).
    virtual Bounds3 bounds(uint32_t prim) const = 0;
    /// Box of the whole shape.
    virtual Bounds3 bounds() const = 0;
    /// Appends boxes that together cover primitive `prim` and every hit that
    /// intersect(prim, ..., opt) can report, for an accelerator to index one
    /// by one: for a long slanted primitive, whose one box is mostly empty, a
    /// few shorter boxes are met by far fewer rays (the idea of Embree's
    /// spatial splits for triangles). Each box stands for the whole primitive:
    /// whichever a ray enters, the accelerator tests the whole primitive, so a
    /// ray that enters several tests it more than once and gets the same
    /// answer. Default: bounds(prim) alone.
    virtual void appendCoveringBoxes(uint32_t prim, const IntersectOptions& opt,
                                     std::vector<Bounds3>& out) const {
        (void)opt;
        out.push_back(bounds(prim));
    }

    /// Closest accepted hit on primitive `prim` with tMin < t < tMax (strict,
    /// NaN-safe), or nothing.
    virtual std::optional<ShapeHit> intersect(uint32_t prim, const Ray& ray, double tMin,
                                              double tMax, const IntersectOptions& opt) const = 0;
    /// Any accepted hit on primitive `prim` with tMin < t < tMax. An override
    /// must answer exactly intersect(...).has_value(): an accelerator may ask
    /// either for the same feeler (Embree's opaque feelers and shadow-cache
    /// hints ask this; the naive loop's filtered objects ask intersect()).
    virtual bool occluded(uint32_t prim, const Ray& ray, double tMin, double tMax,
                          const IntersectOptions& opt) const {
        return intersect(prim, ray, tMin, tMax, opt).has_value();
    }

    /// A hit on some primitive of the shape: which one, and where.
    struct PrimitiveHit {
        uint32_t prim = 0;
        ShapeHit hit;
    };
    /// Closest accepted hit over all primitives (the naive loop's inner loop);
    /// on an exact tie the lower primitive index wins. Shapes with many
    /// primitives override it with a tighter loop.
    virtual std::optional<PrimitiveHit> intersectAny(const Ray& ray, double tMin, double tMax,
                                                     const IntersectOptions& opt) const;
    /// Whether any primitive is hit with tMin < t < tMax.
    virtual bool occludedAny(const Ray& ray, double tMin, double tMax,
                             const IntersectOptions& opt) const;

    /// Point, normals and (for Derivatives and Complete) surface parameters of a
    /// hit previously returned by intersect() for primitive `prim`.
    virtual SurfaceGeometry surfaceAt(uint32_t prim, const Ray& ray, const ShapeHit& hit,
                                      const IntersectOptions& opt,
                                      SurfaceDetail detail) const = 0;

    /// Human-readable kind, for statistics and error messages ("sphere").
    virtual const char* kind() const = 0;

    /// \brief Throws std::invalid_argument when the shape's data cannot be
    ///   intersected safely (a mesh index out of range); accelerators call it
    ///   before they touch any primitive.
    virtual void validate() const {}

    /// Capability: the shape's triangles when an accelerator may take them as
    /// native triangles (Embree's triangle geometry), null otherwise.
    virtual const TriangleMesh* nativeTriangles() const { return nullptr; }

    /// Which rays leaving the shape could meet it again (Revisit). Shapes
    /// with more than one primitive answer Any: the accelerators skip whole
    /// objects.
    virtual Revisit revisit() const { return Revisit::Any; }

    /// Whether the shading normal differs from the geometric one somewhere
    /// (interpolated vertex normals): the "smooth_normals" effect.
    virtual bool hasShadingNormals() const { return false; }

    Sidedness sidedness() const { return m_sides; }
    void setSidedness(Sidedness s) { m_sides = s; }

protected:
    Sidedness m_sides = Sidedness::Outside;
};

}  // namespace raylab
