#include "renderer/accel/naive_accelerator.h"

#include <chrono>

#include "renderer/timing.h"

namespace raylab {

namespace {

/// Both back ends treat a ray they cannot trace (non-finite, zero direction,
/// empty or NaN interval) as a miss, so they agree on it too.
bool traceable(const Ray& ray, double tMin, double tMax) {
    return isFinite(ray.o) && isFinite(ray.d) && ray.d != Vec3{0, 0, 0} && tMin < tMax;
}

}  // namespace

NaiveAccelerator::NaiveAccelerator(const Scene& scene, const AccelOptions& options)
    : m_options(options.intersect) {
    const auto start = std::chrono::steady_clock::now();
    validateShapes(scene, "naive");
    m_shapes.reserve(scene.objects.size());
    for (const Object& o : scene.objects) m_shapes.push_back(o.shape.get());
    m_buildSeconds = secondsSince(start);
}

std::optional<Hit> NaiveAccelerator::intersect(const Ray& ray, double tMin, double tMax) const {
    if (!traceable(ray, tMin, tMax)) return std::nullopt;
    std::optional<Hit> best;
    // Each hit shrinks the interval, so later objects only count if closer;
    // on an exact tie the earlier object in scene order wins.
    for (uint32_t i = 0; i < m_shapes.size(); ++i) {
        const Shape* shape = m_shapes[i];
        if (!shape) continue;
        if (const auto h = shape->intersectAny(ray, tMin, tMax, m_options)) {
            tMax = h->hit.t;
            best = Hit{h->hit.t, i, h->prim, h->hit.u, h->hit.v};
        }
    }
    return best;
}

bool NaiveAccelerator::occluded(const Ray& ray, double tMin, double tMax) const {
    if (!traceable(ray, tMin, tMax)) return false;
    for (const Shape* shape : m_shapes)
        if (shape && shape->occludedAny(ray, tMin, tMax, m_options)) return true;
    return false;
}

}  // namespace raylab
