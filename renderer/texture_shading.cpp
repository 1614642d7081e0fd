#include "renderer/texture_shading.h"

#include <cmath>

#include "shading/normal_mapping.h"

namespace raylab {

TextureShading::TextureShading(const Scene& scene, const RenderOptions& options)
    : m_scene(scene), m_options(options), m_footprints(usesFootprint(options.textures.filter)) {
    // A footprint per sample: stratified samples are 1/√spp pixels apart.
    if (options.spp > 1) m_spacing = 1.0 / std::sqrt(double(options.spp));
    m_cameraSteps = scene.camera.differentialSteps(options.width, options.height, m_spacing);
    m_cameraCone = scene.camera.cone(options.width, options.height, m_spacing);
    m_lookups.reserve(scene.materials.size());
    for (const Material& m : scene.materials) m_lookups.emplace_back(m, scene.textures);
}

RayFootprint TextureShading::cameraFootprint(const Ray& cameraRay) const {
    if (!m_footprints) return RayFootprint{};
    return cameraFootprint(cameraRay, normalize(cameraRay.d));
}

RayFootprint TextureShading::cameraFootprint(const Ray& cameraRay, const Vec3& unitDir) const {
    // Each footprint built in place (a default one would be zeroed first).
    if (!m_footprints) return RayFootprint{};
    if (m_options.textures.footprint == TextureFootprint::Differentials)
        return RayFootprint{m_scene.camera.differential(cameraRay, unitDir, m_cameraSteps), RayCone{}};
    return RayFootprint{RayDifferential{}, m_cameraCone};
}

HitFootprint TextureShading::atHit(const RayFootprint& fp, const Ray& ray, const Vec3& dir,
                                   double t, const SurfaceInteraction& si) const {
    if (!m_footprints) return HitFootprint{TextureCoords{si.uv, Vec2{}, Vec2{}}, Vec3{}, Vec3{}, 0.0};
    // The unit direction is ray.d / length(ray.d): where squaring is safe
    // (every ray but a degenerate one) that is normalize(ray.d), the
    // integrator's dir, bit for bit, and its divisions are saved.
    const double l2 = dot(ray.d, ray.d);
    const bool safe = squaredLengthIsSafe(l2);
    const double len = safe ? std::sqrt(l2) : length(ray.d);
    const Vec3 d = safe ? dir : ray.d / len;
    // The record is built once at the end from these (a default HitFootprint
    // would be zeroed first, at every hit).
    Vec3Pair dp;
    double coneWidth = 0;
    if (m_options.textures.footprint == TextureFootprint::Differentials) {
        dp = transferDifferentials(fp.differential, d, t * len, si.ng);
    } else {
        coneWidth = fp.cone.widthAt(t * len);
        Vec3 dpdx, dpdy;
        coneFootprint(coneWidth, d, si.ng, si.dpdu, dpdx, dpdy);
        dp = Vec3Pair(dpdx, dpdy);
    }
    Vec2 duvdx, duvdy;
    surfaceParameterChanges(si.dpdu, si.dpdv, dp, duvdx, duvdy);
    return HitFootprint{TextureCoords{si.uv, duvdx, duvdy}, dp.first(), dp.second(), coneWidth};
}

void TextureShading::normalChange(const HitFootprint& hf, const SurfaceInteraction& si,
                                  bool entering, Vec3& dndx, Vec3& dndy) {
    const TextureCoords& tc = hf.coords;
    const double sign = entering ? 1.0 : -1.0;
    dndx = (si.dndu * tc.duvdx.x + si.dndv * tc.duvdx.y) * sign;
    dndy = (si.dndu * tc.duvdy.x + si.dndv * tc.duvdy.y) * sign;
}

double TextureShading::curvature(const SurfaceInteraction& si, bool entering) {
    const double k = meanCurvature(si.dpdu, si.dpdv, si.dndu, si.dndv);
    return entering ? k : -k;
}

SurfaceOptics TextureShading::shade(uint32_t material, SurfaceInteraction& si,
                                    const HitFootprint& hf) const {
    const Material& m = m_scene.materials[material];
    const TextureFilter filter = m_options.textures.filter;
    const MaterialMaps& maps = m.maps;
    const std::vector<Texture>& textures = m_scene.textures;
    if (maps.normal != MaterialMaps::kNone)
        si.ns = normalMappedNormal(si, textures[maps.normal], hf.coords, filter);
    if (maps.bump != MaterialMaps::kNone)
        si.ns = bumpedNormal(si, textures[maps.bump], maps.bumpScale, hf.coords, filter);
    return m_lookups[material].evaluate(m, textures, hf.coords, filter);
}

RayFootprint TextureShading::reflected(const RayFootprint& fp, const HitFootprint& hf,
                                       const SurfaceInteraction& si, bool entering,
                                       const Vec3& d, const Vec3& n) const {
    if (!m_footprints) return fp;
    if (m_options.textures.footprint == TextureFootprint::Differentials) {
        Vec3 dndx, dndy;
        normalChange(hf, si, entering, dndx, dndy);
        return RayFootprint{reflectDifferential(fp.differential, d, n, hf.dpdx, hf.dpdy, dndx, dndy),
                            RayCone{}};
    }
    return RayFootprint{RayDifferential{}, reflectCone(fp.cone, hf.coneWidth, curvature(si, entering))};
}

RayFootprint TextureShading::refracted(const RayFootprint& fp, const HitFootprint& hf,
                                       const SurfaceInteraction& si, bool entering,
                                       const Vec3& d, const Vec3& n, const Vec3& out,
                                       double eta) const {
    if (!m_footprints) return fp;
    if (m_options.textures.footprint == TextureFootprint::Differentials) {
        Vec3 dndx, dndy;
        normalChange(hf, si, entering, dndx, dndy);
        return RayFootprint{refractDifferential(fp.differential, d, n, out, eta, hf.dpdx, hf.dpdy,
                                                dndx, dndy),
                            RayCone{}};
    }
    return RayFootprint{RayDifferential{},
                        refractCone(fp.cone, hf.coneWidth, curvature(si, entering), eta)};
}

}  // namespace raylab
