#pragma once
// The textbook accelerator (Nori's brute-force Accel): the list of scene
// objects, each asked for its closest hit in turn (a mesh loops over its
// triangles). O(N) per ray; the reference the Embree back end is checked
// against and the baseline of the speed comparison. Objects the surface
// filter looks at (cut-outs, transmitters) are walked hit by hit.

#include <optional>
#include <string>
#include <vector>

#include "geometry/ray.h"
#include "renderer/accel/accelerator.h"
#include "renderer/scene.h"
#include "renderer/surface_filter.h"

namespace raylab {

class NaiveAccelerator final : public Accelerator {
public:
    /// Lists every object of the scene, which must outlive the accelerator.
    /// \throws std::invalid_argument for a shape that fails validate().
    explicit NaiveAccelerator(const Scene& scene, const AccelOptions& options = {});

    using Accelerator::intersect;
    using Accelerator::occluded;
    using Accelerator::transmittance;
    /// The object a ray departs from (Departure) is left out of the loop.
    std::optional<Hit> intersect(const Ray& ray, double tMin, double tMax,
                                 Departure from) const override;
    bool occluded(const Ray& ray, double tMin, double tMax, Departure from) const override;
    Color transmittance(const Ray& ray, double tMin, double tMax, Departure from) const override;
    std::string name() const override { return "naive"; }
    double buildSeconds() const override { return m_buildSeconds; }
    FilterCounts filterCounts() const override { return m_filter.counts(); }

private:
    /// Closest hit on object i that the filter does not cut out.
    std::optional<Hit> filteredHit(uint32_t i, const Ray& ray, double tMin, double tMax) const;

    /// Every object's shape in scene order (null for an object without one):
    /// a compact list the loop walks without touching the objects.
    std::vector<const Shape*> m_shapes;
    IntersectOptions m_options;
    SurfaceFilter m_filter;
    double m_buildSeconds = 0;
};

}  // namespace raylab
