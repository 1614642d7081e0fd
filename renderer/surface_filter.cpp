#include "renderer/surface_filter.h"

#include <limits>

#include "shading/texture.h"

namespace raylab {

SurfaceFilter::SurfaceFilter(const Scene& scene, const AccelOptions& options)
    : m_scene(scene),
      m_options(options.intersect),
      m_cutoff(options.alphaCutoff),
      m_filtered(scene.objects.size(), 0) {
    const auto valid = [&](uint32_t m) { return m < scene.materials.size(); };
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        bool transmits = valid(o.material) && scene.materials[o.material].transmissive();
        bool cutsOut = valid(o.material) && scene.materials[o.material].cutsOut(m_cutoff);
        for (uint32_t m : o.faceMaterials) {
            transmits = transmits || (valid(m) && scene.materials[m].transmissive());
            cutsOut = cutsOut || (valid(m) && scene.materials[m].cutsOut(m_cutoff));
        }
        m_filtered[i] = uint8_t((transmits ? kTransmits : 0) | (cutsOut ? kCutsOut : 0));
        m_transmits = m_transmits || transmits;
        m_cutsOut = m_cutsOut || cutsOut;
    }
}

bool SurfaceFilter::cutOut(const Ray& ray, const Hit& candidate) const {
    const Object& o = m_scene.objects[candidate.object];
    const Material& m = m_scene.materials[o.materialOf(candidate.prim)];
    if (!m.cutsOut(m_cutoff)) return false;
    double alpha = m.alpha;
    if (m.maps.alpha != MaterialMaps::kNone) {
        // The mask is looked up at surface parameters both accelerators
        // compute alike: Embree reports a triangle's barycentrics in float,
        // so a triangle's hit is recomputed from the double ray, as the
        // naive loop computes it. Footprint-free (bilinear on the full-size
        // image): a hole must not depend on the ray's history.
        ShapeHit h{candidate.t, candidate.u, candidate.v};
        if (o.shape->nativeTriangles()) {
            constexpr double kInf = std::numeric_limits<double>::infinity();
            const auto exact = o.shape->intersect(candidate.prim, ray, -kInf, kInf, m_options);
            if (!exact) return true;  // a float-only graze: no hit in the naive loop either
            h = *exact;
        }
        const SurfaceGeometry g =
            o.shape->surfaceAt(candidate.prim, ray, h, m_options, SurfaceDetail::Complete);
        const Texture& mask = m_scene.textures[m.maps.alpha];
        alpha *= mask.scalar(TextureCoords{g.uv, {0, 0}, {0, 0}}, TextureFilter::Bilinear);
    }
    if (alpha >= m.cutoff(m_cutoff)) return false;
    ++m_counts.local().cutOut;
    return true;
}

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
