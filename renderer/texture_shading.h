#pragma once
// What the integrator does at a hit when the scene has textures (the
// "textures" effect; untextured scenes never construct this): carry each
// ray's footprint (ray cones or differentials), turn it into the change of
// (u, v) per sample at the hit, look the material's textures up there and
// bend the shading normal by bump and normal maps.

#include <cstdint>
#include <vector>

#include "renderer/render_options.h"
#include "renderer/scene.h"
#include "shading/material_textures.h"
#include "shading/ray_cone.h"
#include "shading/ray_differential.h"

namespace raylab {

/// What a ray carries for texture filtering: one of the two, per --texture-footprint.
struct RayFootprint {
    RayDifferential differential;
    RayCone cone;
};

/// A hit's footprint: where and how wide the textures are looked up, and
/// what the rays it spawns need.
struct HitFootprint {
    TextureCoords coords;   ///< uv and its change per sample
    Vec3 dpdx, dpdy;        ///< change of the hit point per sample
    double coneWidth = 0;   ///< cones: signed width at the hit
};

class TextureShading {
public:
    TextureShading(const Scene& scene, const RenderOptions& options);

    /// The footprint a camera ray starts with (one sample: 1/√spp pixels).
    RayFootprint cameraFootprint(const Ray& cameraRay) const;
    /// The same with normalize(cameraRay.d) known (the integrator computes
    /// it at the camera ray's hit; a ray that misses needs no footprint).
    RayFootprint cameraFootprint(const Ray& cameraRay, const Vec3& unitDir) const;
    /// The footprint at a hit at parameter t of `ray`; `dir` is
    /// normalize(ray.d) (the integrator has it); `si` has at least
    /// SurfaceDetail::Derivatives (uv is not read).
    HitFootprint atHit(const RayFootprint& fp, const Ray& ray, const Vec3& dir, double t,
                       const SurfaceInteraction& si) const;
    /// The values of material `material` (an index into the scene's
    /// materials) at the hit; bends si.ns by its bump or normal map.
    SurfaceOptics shade(uint32_t material, SurfaceInteraction& si, const HitFootprint& hf) const;
    /// Footprints of the mirror and refracted rays leaving the hit: d the
    /// unit incoming direction, n the arriving-side shading normal, out the
    /// new unit direction, eta = etaI / etaT; si as for atHit, `entering` as in the integrator.
    /// The change of the normal (differentials) or the curvature (cones) is
    /// computed here, only for hits that spawn such a ray.
    RayFootprint reflected(const RayFootprint& fp, const HitFootprint& hf,
                           const SurfaceInteraction& si, bool entering, const Vec3& d,
                           const Vec3& n) const;
    RayFootprint refracted(const RayFootprint& fp, const HitFootprint& hf,
                           const SurfaceInteraction& si, bool entering, const Vec3& d,
                           const Vec3& n, const Vec3& out, double eta) const;
    /// The change of the arriving-side shading normal per sample at the hit.
    static void normalChange(const HitFootprint& hf, const SurfaceInteraction& si, bool entering,
                             Vec3& dndx, Vec3& dndy);
    /// Cones: the mean curvature at the hit, > 0 bulging towards the ray.
    static double curvature(const SurfaceInteraction& si, bool entering);

private:
    const Scene& m_scene;
    RenderOptions m_options;
    bool m_footprints;     ///< the filter reads footprints (trilinear, anisotropic)
    double m_spacing = 1;  ///< sample spacing in pixels
    Camera::DifferentialSteps m_cameraSteps;  ///< the camera's per-image part of its differentials
    RayCone m_cameraCone;  ///< every camera ray's cone (the same for the whole image)
    std::vector<MaterialLookups> m_lookups;  ///< per material, its colour lookups
};

}  // namespace raylab
