#pragma once
// The textbook accelerator (Nori's brute-force Accel): a flat list of
// surfaces, one per analytic object and one per triangle, tested one after
// the other. O(N) per ray; the reference the Embree back end is checked
// against and the baseline of the speed comparison.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/bounds.h"
#include "geometry/ray.h"
#include "geometry/shape.h"
#include "geometry/triangle.h"
#include "renderer/accel/accelerator.h"
#include "renderer/scene.h"

namespace raylab {

/// One intersectable entry of the naive list: an analytic shape or a single
/// triangle (its vertices copied in, so the loop touches contiguous memory).
class Surface {
public:
    /// An entry for the analytic shape of object `object`.
    static Surface analytic(const Shape& shape, uint32_t object);
    /// An entry for triangle `prim` of `mesh`, belonging to object `object`.
    static Surface triangle(const TriangleMesh& mesh, uint32_t object, uint32_t prim,
                            Sidedness sides = Sidedness::Both);

    /// \brief Closest hit with tMin < t < tMax, as the accelerator reports it
    ///   (object and primitive filled in), or nothing.
    /// \param wray the same ray with the watertight test's per-ray constants,
    ///   computed once per query by the caller.
    std::optional<Hit> hit(const Ray& ray, const WatertightRay& wray, double tMin,
                           double tMax) const;
    /// Whether anything is hit with tMin < t < tMax (same arguments as hit()).
    bool occluded(const Ray& ray, const WatertightRay& wray, double tMin, double tMax) const;
    /// World-space box of the entry.
    Bounds3 bounds() const;

    uint32_t object() const { return m_object; }
    uint32_t prim() const { return m_prim; }

private:
    Surface() = default;

    const Shape* m_shape = nullptr;  ///< analytic entry; null for a triangle
    std::array<Vec3, 3> m_vertices;  ///< triangle entry
    Sidedness m_sides = Sidedness::Both;  ///< triangle entry: which side can be hit
    /// Whether a triangle hit from direction d is on an accepted side.
    bool acceptsTriangleFacing(const Vec3& d) const;
    uint32_t m_object = 0;
    uint32_t m_prim = 0;
};

class NaiveAccelerator final : public Accelerator {
public:
    /// Lists every primitive of the scene, which must outlive the accelerator.
    explicit NaiveAccelerator(const Scene& scene);

    std::optional<Hit> intersect(const Ray& ray, double tMin, double tMax) const override;
    bool occluded(const Ray& ray, double tMin, double tMax) const override;
    std::string name() const override { return "naive"; }

    /// The flat list the loop runs over (one entry per primitive).
    const std::vector<Surface>& surfaces() const { return m_surfaces; }

private:
    std::vector<Surface> m_surfaces;
};

}  // namespace raylab
