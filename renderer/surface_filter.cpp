#include "renderer/surface_filter.h"

namespace raylab {

SurfaceFilter::SurfaceFilter(const Scene& scene)
    : m_scene(scene), m_filtered(scene.objects.size(), 0) {
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        bool transmits = o.material < scene.materials.size() &&
                         scene.materials[o.material].transmissive();
        for (uint32_t m : o.faceMaterials)
            transmits = transmits || (m < scene.materials.size() && scene.materials[m].transmissive());
        m_filtered[i] = transmits;
        m_active = m_active || transmits;
    }
}

bool SurfaceFilter::cutOut(const Ray&, const Hit&) const { return false; }

Color SurfaceFilter::transmission(const Ray&, const Hit& candidate) const {
    const Object& o = m_scene.objects[candidate.object];
    return m_scene.materials[o.materialOf(candidate.prim)].kt;
}

FilterCounts SurfaceFilter::counts() const {
    FilterCounts sum;
    for (const FilterCounts& c : m_counts) sum += c;
    return sum;
}

}  // namespace raylab
