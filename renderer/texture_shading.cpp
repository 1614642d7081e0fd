#include "renderer/texture_shading.h"

#include <cmath>

#include "shading/material_textures.h"
#include "shading/normal_mapping.h"

namespace raylab {

TextureShading::TextureShading(const Scene& scene, const RenderOptions& options)
    : m_scene(scene), m_options(options), m_footprints(usesFootprint(options.textures.filter)) {
    // A footprint per sample: stratified samples are 1/√spp pixels apart.
    if (options.spp > 1) m_spacing = 1.0 / std::sqrt(double(options.spp));
    m_cameraSteps = scene.camera.differentialSteps(options.width, options.height, m_spacing);
    m_cameraCone = scene.camera.cone(options.width, options.height, m_spacing);
}

RayFootprint TextureShading::cameraFootprint(const Ray& cameraRay) const {
    if (!m_footprints) return RayFootprint{};
    return cameraFootprint(cameraRay, normalize(cameraRay.d));
}

RayFootprint TextureShading::cameraFootprint(const Ray& cameraRay, const Vec3& unitDir) const {
    RayFootprint fp;
    if (!m_footprints) return fp;
    if (m_options.textures.footprint == TextureFootprint::Differentials)
        fp.differential = m_scene.camera.differential(cameraRay, unitDir, m_cameraSteps);
    else
        fp.cone = m_cameraCone;
    return fp;
}

HitFootprint TextureShading::atHit(const RayFootprint& fp, const Ray& ray, const Vec3& dir,
                                   double t, const SurfaceInteraction& si) const {
    HitFootprint hf;
    hf.coords.uv = si.uv;
    if (!m_footprints) return hf;
    // The unit direction is ray.d / length(ray.d): where squaring is safe
    // (every ray but a degenerate one) that is normalize(ray.d), the
    // integrator's dir, bit for bit, and its divisions are saved.
    const double l2 = dot(ray.d, ray.d);
    const bool safe = squaredLengthIsSafe(l2);
    const double len = safe ? std::sqrt(l2) : length(ray.d);
    const Vec3 d = safe ? dir : ray.d / len;
    if (m_options.textures.footprint == TextureFootprint::Differentials) {
        transferDifferential(fp.differential, d, t * len, si.ng, hf.dpdx, hf.dpdy);
    } else {
        hf.coneWidth = fp.cone.widthAt(t * len);
        coneFootprint(hf.coneWidth, d, si.ng, si.dpdu, hf.dpdx, hf.dpdy);
    }
    TextureCoords& tc = hf.coords;
    surfaceParameterChanges(si.dpdu, si.dpdv, hf.dpdx, hf.dpdy, tc.duvdx, tc.duvdy);
    return hf;
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

SurfaceOptics TextureShading::shade(const Material& m, SurfaceInteraction& si,
                                    const HitFootprint& hf) const {
    const TextureFilter filter = m_options.textures.filter;
    const MaterialMaps& maps = m.maps;
    const std::vector<Texture>& textures = m_scene.textures;
    if (maps.normal != MaterialMaps::kNone)
        si.ns = normalMappedNormal(si, textures[maps.normal], hf.coords, filter);
    if (maps.bump != MaterialMaps::kNone)
        si.ns = bumpedNormal(si, textures[maps.bump], maps.bumpScale, hf.coords, filter);
    return evaluateOptics(m, textures, hf.coords, filter);
}

RayFootprint TextureShading::reflected(const RayFootprint& fp, const HitFootprint& hf,
                                       const SurfaceInteraction& si, bool entering,
                                       const Vec3& d, const Vec3& n) const {
    if (!m_footprints) return fp;
    RayFootprint out;
    if (m_options.textures.footprint == TextureFootprint::Differentials) {
        Vec3 dndx, dndy;
        normalChange(hf, si, entering, dndx, dndy);
        out.differential = reflectDifferential(fp.differential, d, n, hf.dpdx, hf.dpdy, dndx, dndy);
    } else {
        out.cone = reflectCone(fp.cone, hf.coneWidth, curvature(si, entering));
    }
    return out;
}

RayFootprint TextureShading::refracted(const RayFootprint& fp, const HitFootprint& hf,
                                       const SurfaceInteraction& si, bool entering,
                                       const Vec3& d, const Vec3& n, const Vec3& out,
                                       double eta) const {
    if (!m_footprints) return fp;
    RayFootprint r;
    if (m_options.textures.footprint == TextureFootprint::Differentials) {
        Vec3 dndx, dndy;
        normalChange(hf, si, entering, dndx, dndy);
        r.differential = refractDifferential(fp.differential, d, n, out, eta, hf.dpdx, hf.dpdy,
                                             dndx, dndy);
    } else {
        r.cone = refractCone(fp.cone, hf.coneWidth, curvature(si, entering), eta);
    }
    return r;
}

}  // namespace raylab
