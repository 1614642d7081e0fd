#include "renderer/effects.h"

#include "renderer/render_options.h"
#include "renderer/scene.h"
#include "renderer/surface_filter.h"

namespace raylab {

std::vector<std::string> EffectSet::names() const {
    std::vector<std::string> n;
    if (has(kShadows)) n.push_back("shadows");
    if (has(kHighlights)) n.push_back("highlights");
    if (has(kReflection)) n.push_back("reflection");
    if (has(kRefraction)) n.push_back("refraction");
    if (has(kTextures)) n.push_back("textures");
    if (smoothNormals) n.push_back("smooth_normals");
    if (antialiasing) n.push_back("antialiasing");
    if (aovs) n.push_back("aovs");
    if (filteredShadows) n.push_back("filtered_shadows");
    if (cutOuts) n.push_back("cut_outs");
    return n;
}

EffectSet analyseEffects(const Scene& scene, const RenderOptions& options) {
    EffectSet e;
    // Only materials that some object uses count.
    std::vector<bool> used(scene.materials.size(), false);
    for (const Object& o : scene.objects) {
        if (o.material < used.size()) used[o.material] = true;
        for (uint32_t m : o.faceMaterials)
            if (m < used.size()) used[m] = true;
    }
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (used[i] && scene.materials[i].maps.any()) e.kernel |= kTextures;
    if (options.forceAllEffects) {
        e.kernel |= kAllKernelEffects;
    } else {
        const bool secondary = options.maxDepth > 1;
        for (size_t i = 0; i < scene.materials.size(); ++i) {
            if (!used[i]) continue;
            const Material& m = scene.materials[i];
            // SPD's procedure counts shadow rays from every surface.
            if (!scene.lights.empty() && (m.hasLocalShading() || options.spd)) e.kernel |= kShadows;
            if (!scene.lights.empty() && !m.ks.isBlack()) e.kernel |= kHighlights;
            const bool spdReflects = options.spd && (!m.ks.isBlack() || m.transmissive());
            if (secondary && (m.reflective() || spdReflects)) e.kernel |= kReflection;
            if (secondary && m.transmissive()) e.kernel |= kRefraction;
        }
    }
    for (const Object& o : scene.objects)
        if (o.shape && o.shape->hasShadingNormals()) e.smoothNormals = true;
    e.antialiasing = options.spp > 1 || options.adaptiveThreshold > 0;
    e.filteredShadows = options.shadows == ShadowMode::Filtered && e.has(kShadows) &&
                        SurfaceFilter(scene, options.accelOptions).transmits();
    e.cutOuts = SurfaceFilter(scene, options.accelOptions).cutsOut();
    e.aovs = options.wantAovs;
    return e;
}

}  // namespace raylab
