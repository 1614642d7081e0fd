#pragma once
// The textbook accelerator (Nori's brute-force Accel): the list of scene
// objects, each asked for its closest hit in turn (a mesh loops over its
// triangles). O(N) per ray; the reference the Embree back end is checked
// against and the baseline of the speed comparison.

#include <optional>
#include <string>
#include <vector>

#include "geometry/ray.h"
#include "renderer/accel/accelerator.h"
#include "renderer/scene.h"

namespace raylab {

class NaiveAccelerator final : public Accelerator {
public:
    /// Lists every object of the scene, which must outlive the accelerator.
    /// \throws std::invalid_argument for a shape that fails validate().
    explicit NaiveAccelerator(const Scene& scene, const AccelOptions& options = {});

    std::optional<Hit> intersect(const Ray& ray, double tMin, double tMax) const override;
    bool occluded(const Ray& ray, double tMin, double tMax) const override;
    std::string name() const override { return "naive"; }
    double buildSeconds() const override { return m_buildSeconds; }

private:
    /// Every object's shape in scene order (null for an object without one):
    /// a compact list the loop walks without touching the objects.
    std::vector<const Shape*> m_shapes;
    IntersectOptions m_options;
    double m_buildSeconds = 0;
};

}  // namespace raylab
