#include "renderer/accel/naive_accelerator.h"

#include <chrono>

#include "renderer/accel/transmittance.h"
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
    : m_options(options.intersect), m_filter(scene, options) {
    const auto start = std::chrono::steady_clock::now();
    validateShapes(scene, "naive");
    m_shapes.reserve(scene.objects.size());
    for (const Object& o : scene.objects) m_shapes.push_back(o.shape.get());
    m_buildSeconds = secondsSince(start);
}

std::optional<Hit> NaiveAccelerator::filteredHit(uint32_t i, const Ray& ray, double tMin,
                                                 double tMax) const {
    const Shape& shape = *m_shapes[i];
    std::optional<Hit> best;
    for (uint32_t prim = 0, n = shape.primitiveCount(); prim < n; ++prim) {
        // A cut-out hit is no hit: the next one along the ray may count.
        for (double from = tMin;;) {
            const auto h = shape.intersect(prim, ray, from, tMax, m_options);
            if (!h) break;
            const Hit hit{h->t, i, prim, h->u, h->v};
            if (m_filter.cutOut(ray, hit)) {
                from = h->t;
                continue;
            }
            tMax = h->t;
            best = hit;
            break;
        }
    }
    return best;
}

std::optional<Hit> NaiveAccelerator::intersect(const Ray& ray, double tMin, double tMax,
                                               Departure from) const {
    if (!traceable(ray, tMin, tMax)) return std::nullopt;
    std::optional<Hit> best;
    // Each hit shrinks the interval, so later objects only count if closer;
    // on an exact tie the earlier object in scene order wins.
    for (uint32_t i = 0; i < m_shapes.size(); ++i) {
        const Shape* shape = m_shapes[i];
        if (!shape || i == from.object) continue;
        if (m_filter.filters(i)) {
            if (const auto h = filteredHit(i, ray, tMin, tMax)) {
                tMax = h->t;
                best = h;
            }
        } else if (const auto h = shape->intersectAny(ray, tMin, tMax, m_options)) {
            tMax = h->hit.t;
            best = Hit{h->hit.t, i, h->prim, h->hit.u, h->hit.v};
        }
    }
    return best;
}

bool NaiveAccelerator::occluded(const Ray& ray, double tMin, double tMax, Departure from) const {
    if (!traceable(ray, tMin, tMax)) return false;
    for (uint32_t i = 0; i < m_shapes.size(); ++i) {
        const Shape* shape = m_shapes[i];
        if (!shape || i == from.object) continue;
        // Transmitters are opaque here (opaque shadows); only holes let light by.
        if (m_filter.filters(i) ? filteredHit(i, ray, tMin, tMax).has_value()
                                : shape->occludedAny(ray, tMin, tMax, m_options))
            return true;
    }
    return false;
}

Color NaiveAccelerator::transmittance(const Ray& ray, double tMin, double tMax,
                                      Departure from) const {
    if (!m_filter.active()) return occluded(ray, tMin, tMax, from) ? Color{} : Color(1.0);
    if (!traceable(ray, tMin, tMax)) return Color(1.0);
    TransmittanceAccumulator acc;
    for (uint32_t i = 0; i < m_shapes.size(); ++i) {
        const Shape* shape = m_shapes[i];
        if (!shape || i == from.object) continue;
        if (!m_filter.filters(i)) {
            if (shape->occludedAny(ray, tMin, tMax, m_options)) return Color{};
            continue;
        }
        // Every crossing of every primitive in (tMin, tMax).
        for (uint32_t prim = 0, n = shape->primitiveCount(); prim < n; ++prim) {
            for (double from = tMin;;) {
                const auto h = shape->intersect(prim, ray, from, tMax, m_options);
                if (!h) break;
                from = h->t;
                const Hit hit{h->t, i, prim, h->u, h->v};
                if (m_filter.cutOut(ray, hit)) continue;
                const Color c = m_filter.transmission(ray, hit);
                if (c.isBlack()) return Color{};
                acc.add(i, prim, h->t, c);
            }
        }
    }
    m_filter.countCrossings(acc.size());
    return acc.product();
}

}  // namespace raylab
